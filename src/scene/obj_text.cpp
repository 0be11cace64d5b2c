#include "scene/obj_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

#include "scene/text.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The text's lines: up to '\n', comments ('#' to the end) and surrounding blanks removed.
class TextLines {
public:
  explicit TextLines(std::string_view s) : s_(s) {}
  // False at the end; else `line` (possibly empty), `raw` (the whole line) and its number.
  bool next(std::string_view& line, std::string_view& raw, int& number) {
    if (at_ >= s_.size()) return false;
    const char* b = s_.data() + at_;
    const void* nl = std::memchr(b, '\n', s_.size() - at_);
    const std::size_t len = nl ? std::size_t(static_cast<const char*>(nl) - b) : s_.size() - at_;
    raw = std::string_view(b, len);
    at_ += len + 1;
    number = ++number_;
    line = raw;
    if (const void* h = std::memchr(line.data(), '#', line.size()))
      line = line.substr(0, std::size_t(static_cast<const char*>(h) - line.data()));
    while (!line.empty() && blank(line.front()))
      line.remove_prefix(1);
    while (!line.empty() && blank(line.back()))
      line.remove_suffix(1);
    return true;
  }

private:
  std::string_view s_;
  std::size_t at_ = 0;
  int number_ = 0;
};

// The next blank-separated token of `rest` (empty at the end), removed from it.
std::string_view token(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && blank(rest[i]))
    ++i;
  std::size_t j = i;
  while (j < rest.size() && !blank(rest[j]))
    ++j;
  std::string_view t = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return t;
}

class Reader {
public:
  Reader(const std::string& path, std::string_view text, const MtllibCheck& on_mtllib)
      : path_(path), text_(text), on_mtllib_(on_mtllib) {}

  ObjText read() {
    count();
    out_.materials_obj = "v 0 0 0\nf 1 1 1\n";
    std::string_view line, raw;
    int number = 0;
    TextLines lines(text_);
    while (lines.next(line, raw, number))
      if (!line.empty()) read_line(line, raw, number);
    if (out_.face_size.empty()) throw InputError(path_, 0, "no faces");
    return std::move(out_);
  }

private:
  // Index ranges are checked against the whole file's counts (a face may name a later vertex).
  void count() {
    std::size_t faces = 0;
    std::string_view line, raw;
    int number = 0;
    TextLines lines(text_);
    while (lines.next(line, raw, number)) {
      const std::string_view k = text::keyword(line);
      if (k == "v")
        ++total_[0];
      else if (k == "vt")
        ++total_[1];
      else if (k == "vn")
        ++total_[2];
      else if (k == "f")
        ++faces;
    }
    // Sized once (growing them by doubling copied and page-faulted a third of the load).
    out_.positions.reserve(3 * std::size_t(total_[0]));
    out_.texcoords.reserve(2 * std::size_t(total_[1]));
    out_.normals.reserve(3 * std::size_t(total_[2]));
    out_.corners.reserve(3 * faces); // triangles, the common case
    out_.face_size.reserve(faces);
    out_.face_segment.reserve(faces);
  }

  [[noreturn]] void fail(const std::string& why) const { throw InputError(path_, line_, why); }

  // At least `min_count` tokens; the first `max_count` must be numbers; the first `keep` numbers
  // are stored (0 for one absent, as tinyobjloader stores it).
  void numbers(std::string_view k, std::string_view rest, std::size_t min_count,
               std::size_t max_count, std::size_t keep, std::vector<float>& to) {
    std::string_view t[3];
    std::size_t n = 0;
    for (std::string_view tok = token(rest); !tok.empty(); tok = token(rest))
      if (n++ < max_count) t[n - 1] = tok;
    if (n < min_count)
      fail("'" + std::string(k) + "' needs " + std::to_string(min_count) + " numbers");
    float v[3] = {0, 0, 0};
    for (std::size_t i = 0; i < std::min(n, max_count); ++i) {
      const auto f = text::to_float(t[i]);
      if (!f) fail(text::float_problem(t[i]));
      v[i] = *f;
    }
    to.insert(to.end(), v, v + keep);
  }

  void face(std::string_view rest) {
    static const char* what[3] = {"vertex", "texture coordinate", "normal"};
    std::size_t corners = 0;
    for (std::string_view r = rest; !token(r).empty();)
      ++corners;
    if (corners < 3) fail("a face needs at least 3 vertices");
    if (corners > 255) fail("a face has more than 255 vertices");
    for (std::string_view ref = token(rest); !ref.empty(); ref = token(rest)) {
      if (ref.back() == '/' || std::count(ref.begin(), ref.end(), '/') > 2)
        fail("bad face vertex '" + std::string(ref) + "'");
      int idx[3] = {-1, -1, -1};
      std::string_view r = ref;
      for (int part = 0; part < 3 && !r.empty(); ++part) {
        const std::size_t slash = r.find('/');
        const std::string_view num = r.substr(0, slash);
        r = slash == std::string_view::npos ? std::string_view() : r.substr(slash + 1);
        if (num.empty() && part > 0) continue; // v//vn
        const auto v = text::to_int(num);
        if (!v) fail("bad face vertex '" + std::string(ref) + "'");
        const long long one_based = *v < 0 ? seen_[part] + *v + 1 : *v;
        if (*v == 0 || one_based < 1 || one_based > total_[part])
          fail(std::string(what[part]) + " index " + std::to_string(*v) +
               " out of range (the file has " + std::to_string(total_[part]) + ")");
        idx[part] = int(one_based - 1);
      }
      out_.corners.push_back({idx[0], idx[1], idx[2]});
    }
    out_.face_size.push_back(std::uint8_t(corners));
    out_.face_segment.push_back(segment_);
  }

  void material_line(std::string_view raw) {
    out_.materials_obj.append(raw);
    out_.materials_obj += "\nf 1 1 1\n";
    ++segment_;
  }

  void read_line(std::string_view line, std::string_view raw, int number) {
    line_ = number;
    const std::string_view k = text::keyword(line);
    std::string_view rest = line.substr(k.size());
    if (k == "v") {
      numbers(k, rest, 3, 3, 3, out_.positions);
      ++seen_[0];
    } else if (k == "vt") {
      numbers(k, rest, 1, 3, 2, out_.texcoords);
      ++seen_[1];
    } else if (k == "vn") {
      numbers(k, rest, 3, 3, 3, out_.normals);
      ++seen_[2];
    } else if (k == "f") {
      face(rest);
    } else if (k == "mtllib") {
      std::string_view names = rest;
      if (token(names).empty()) fail("mtllib needs a file name");
      for (std::string_view t = token(rest); !t.empty(); t = token(rest))
        on_mtllib_(std::string(t), number); // checked here: its faults come in file order
      material_line(raw);
    } else if (line.starts_with("usemtl")) { // tinyobjloader's test: the prefix alone
      if (k == "usemtl" && token(rest).empty()) fail("usemtl needs a name");
      material_line(raw);
    }
  }

  const std::string& path_;
  std::string_view text_;
  const MtllibCheck& on_mtllib_;
  ObjText out_;
  long long total_[3] = {0, 0, 0}, seen_[3] = {0, 0, 0}; // v, vt, vn
  std::uint32_t segment_ = 0;
  int line_ = 0;
};

} // namespace

ObjText read_obj_text(const std::string& path, const std::string& text,
                      const MtllibCheck& on_mtllib) {
  return Reader(path, text, on_mtllib).read();
}

} // namespace zc
