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

// Row by row, a row not touched yet read as its background (uncovered: depth 1), not filled in:
// the rows of a final picture nothing was drawn in cost the host no page.
bool same_depth_map(const Framebuffer& fb, const std::vector<float>& map) {
  if (map.size() != fb.pixel_count()) return false;
  const RowSet& rows = fb.rows();
  const std::size_t W = std::size_t(fb.width());
  const float* depth = fb.depth_data();
  const std::uint32_t* ids = fb.ids_data();
  for (int r = 0; r < rows.count(); ++r) {
    const bool untouched = fb.untouched(rows.begin + r * rows.stride);
    for (std::size_t i = std::size_t(r) * W; i < std::size_t(r + 1) * W; ++i) {
      const float d = untouched || ids[i] == kNoTriangle ? 1.0f : depth[i];
      if (!(d == map[i])) return false; // as float ==
    }
  }
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
      !EVP_DigestUpdate(ctx.get(), dims, sizeof dims))
    throw std::runtime_error("SHA-256 failed");
  // Row by row (the same digest as of the whole plane), a row not touched yet as its background.
  const RowSet& rows = fb.rows();
  const std::size_t W = std::size_t(fb.width());
  std::vector<std::uint8_t> background;
  for (int r = 0; r < rows.count(); ++r) {
    const std::uint8_t* row = fb.rgb_data() + 3 * W * std::size_t(r);
    if (fb.untouched(rows.begin + r * rows.stride)) {
      if (background.empty())
        for (std::size_t x = 0; x < W; ++x)
          background.insert(background.end(), fb.background_rgb(), fb.background_rgb() + 3);
      row = background.data();
    }
    if (!EVP_DigestUpdate(ctx.get(), row, 3 * W)) throw std::runtime_error("SHA-256 failed");
  }
  if (!EVP_DigestFinal_ex(ctx.get(), md, &len)) throw std::runtime_error("SHA-256 failed");
  std::string hex;
  char buf[3];
  for (unsigned i = 0; i < len; ++i) {
    std::snprintf(buf, sizeof buf, "%02x", md[i]);
    hex += buf;
  }
  return hex;
}

} // namespace zc
