#pragma once
// Image files through the OpenImageIO module (src/image), loaded with dlopen on first use: a run
// that reads and writes no image never loads OpenImageIO (start-up time).
#include <cstdint>
#include <string>
#include <vector>

namespace zc::image_module {

// Writes 8-bit (or float) pixels; throws std::runtime_error naming the path and the reason.
void write(const std::string& path, int width, int height, int channels, bool is_float,
           const void* data);

struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> data; // 8 bits per channel, rows top to bottom
};
enum class ReadStatus { Ok = 0, CannotOpen = 1, UnusableSize = 2, CannotDecode = 3 };
// Reads an image as 8-bit channels; `error` says why when the status is not Ok.
ReadStatus read(const std::string& path, Pixels& out, std::string& error);

} // namespace zc::image_module
