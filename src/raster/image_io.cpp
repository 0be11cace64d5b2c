#include "raster/image_io.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include <openssl/evp.h>

#include "util/image_module.hpp"

namespace zc {

void write_png(const Framebuffer& fb, const std::string& path) {
  image_module::write(path, fb.width(), fb.rows().count(), 3, false, fb.rgb().data());
}

std::vector<float> depth_map(const Framebuffer& fb) {
  std::vector<float> d(fb.depth().begin(), fb.depth().end());
  for (std::size_t i = 0; i < d.size(); ++i)
    if (fb.ids()[i] == kNoTriangle) d[i] = 1.0f;
  return d;
}

bool same_depth_map(const Framebuffer& fb, const std::vector<float>& map) {
  const auto& depth = fb.depth();
  const auto& ids = fb.ids();
  if (map.size() != depth.size()) return false;
  for (std::size_t i = 0; i < map.size(); ++i)
    if (!((ids[i] == kNoTriangle ? 1.0f : depth[i]) == map[i])) return false; // as float ==
  return true;
}

void write_depth_exr(const Framebuffer& fb, const std::string& path) {
  const std::vector<float> d = depth_map(fb);
  image_module::write(path, fb.width(), fb.rows().count(), 1, true, d.data());
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
