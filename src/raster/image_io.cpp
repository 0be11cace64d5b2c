#include "raster/image_io.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <openssl/evp.h>

namespace zc {

static void write_image(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type,
                        const void* data) {
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write image: " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, channels, type);
  if (!out->open(path, spec) || !out->write_image(type, data) || !out->close())
    throw std::runtime_error(path + ": cannot write image: " + out->geterror());
}

void write_png(const Framebuffer& fb, const std::string& path) {
  write_image(path, fb.width(), fb.rows().count(), 3, OIIO::TypeDesc::UINT8, fb.rgb().data());
}

void write_depth_exr(const Framebuffer& fb, const std::string& path) {
  std::vector<float> d(fb.depth());
  for (std::size_t i = 0; i < d.size(); ++i)
    if (fb.ids()[i] == kNoTriangle) d[i] = 1.0f;
  write_image(path, fb.width(), fb.rows().count(), 1, OIIO::TypeDesc::FLOAT, d.data());
}

std::string image_sha256(const Framebuffer& fb) {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  const std::uint32_t dims[2] = {std::uint32_t(fb.width()), std::uint32_t(fb.rows().count())};
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  if (!ctx || !EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) ||
      !EVP_DigestUpdate(ctx.get(), dims, sizeof dims) ||
      !EVP_DigestUpdate(ctx.get(), fb.rgb().data(), fb.rgb().size()) ||
      !EVP_DigestFinal_ex(ctx.get(), md, &len))
    throw std::runtime_error("SHA-256 failed");
  std::string hex;
  char buf[3];
  for (unsigned i = 0; i < len; ++i) {
    std::snprintf(buf, sizeof buf, "%02x", md[i]);
    hex += buf;
  }
  return hex;
}

} // namespace zc
