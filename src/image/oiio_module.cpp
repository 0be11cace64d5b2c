// The only code that links OpenImageIO. It is built as a module that util/image_module loads on
// the first image read or written, so that a run touching no image does not pay for resolving the
// symbols of OpenImageIO's ~280 shared libraries at start-up.
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include <OpenImageIO/imageio.h>

namespace {
int fail(int code, const std::string& msg, char* err, unsigned long errlen) {
  if (errlen > 0) {
    std::strncpy(err, msg.c_str(), errlen - 1);
    err[errlen - 1] = '\0';
  }
  return code;
}
} // namespace

extern "C" {

// Writes w x h pixels of `channels` channels (8-bit, or 32-bit float if is_float); 0 when done.
int zcube_image_write(const char* path, int w, int h, int channels, int is_float, const void* data,
                      char* err, unsigned long errlen) {
  const auto parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  const OIIO::TypeDesc type = is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return fail(1, OIIO::geterror(), err, errlen);
  OIIO::ImageSpec spec(w, h, channels, type);
  // No capture date (OpenEXR's capDate is the write time unless given): the same pixels give the
  // same bytes.
  spec.attribute("DateTime", "");
  if (!out->open(path, spec) || !out->write_image(type, data) || !out->close())
    return fail(1, out->geterror(), err, errlen);
  return 0;
}

// Reads an image as 8-bit channels into *pixels (malloc'd, the caller frees): 0 when done,
// 1 cannot open, 2 unusable size, 3 cannot decode.
int zcube_image_read(const char* path, int* w, int* h, int* channels, unsigned char** pixels,
                     char* err, unsigned long errlen) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return fail(1, OIIO::geterror(), err, errlen);
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > 65536 ||
      spec.height > 65536)
    return fail(2, "", err, errlen);
  *w = spec.width;
  *h = spec.height;
  *channels = spec.nchannels;
  const std::size_t n = std::size_t(*w) * std::size_t(*h) * std::size_t(*channels);
  *pixels = static_cast<unsigned char*>(std::malloc(n));
  if (!*pixels) return fail(2, "", err, errlen);
  if (!in->read_image(0, 0, 0, *channels, OIIO::TypeDesc::UINT8, *pixels)) {
    std::free(*pixels);
    *pixels = nullptr;
    return fail(3, in->geterror(), err, errlen);
  }
  return 0;
}

} // extern "C"
