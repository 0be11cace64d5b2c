#include "scene/bezier.hpp"

#include <array>
#include <map>
#include <mutex>

#include "scene/text.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

struct Lines {
  std::vector<std::string_view> lines;
  std::size_t next = 0;
  const std::string& path;
  // Next non-empty line and its 1-based number.
  std::string_view get(int& lineno, const char* what) {
    while (next < lines.size()) {
      std::string_view l = text::trim(lines[next++]);
      if (!l.empty()) {
        lineno = int(next);
        return l;
      }
    }
    const int last = int(lines.size()) - (!lines.empty() && lines.back().empty() ? 1 : 0);
    throw InputError(path, last, std::string("truncated file: expected ") + what);
  }
};

std::vector<std::string_view> split_lines(const std::string& s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i <= s.size()) {
    std::size_t j = s.find('\n', i);
    if (j == std::string::npos) j = s.size();
    out.emplace_back(s.data() + i, j - i);
    i = j + 1;
  }
  return out;
}

long long count_line(Lines& in, const char* what, long long max, int* line = nullptr) {
  int ln = 0;
  auto l = in.get(ln, what);
  auto v = text::to_int(l);
  if (!v || *v < 1 || *v > max)
    throw InputError(in.path, ln,
                     std::string("expected ") + what + ", got '" + std::string(l) + "'");
  if (line) *line = ln;
  return *v;
}

glm::dvec3 point_line(Lines& in, bool commas) {
  int ln = 0;
  auto l = in.get(ln, "a control point");
  auto tok = text::split(l, commas);
  if (tok.size() != 3) throw InputError(in.path, ln, "expected 3 coordinates");
  glm::dvec3 p;
  for (int k = 0; k < 3; ++k) {
    auto v = text::to_double(tok[std::size_t(k)]);
    if (!v)
      throw InputError(in.path, ln,
                       "not a finite number: '" + std::string(tok[std::size_t(k)]) + "'");
    p[k] = *v;
  }
  return p;
}

} // namespace

std::vector<BezierPatch> parse_bezier(const std::string& s, const std::string& path) {
  Lines in{split_lines(s), 0, path};
  const bool bpt = path.size() >= 4 && text::lower(path.substr(path.size() - 4)) == ".bpt";
  // Counts are checked against the lines left before anything is allocated: each patch needs 17
  // lines (.bpt) or one (teaset), each control point one, so a short file cannot ask for gigabytes.
  const long long lines_left = (long long)in.lines.size();
  const long long n = count_line(in, "the patch count", 1000000);
  if (n > lines_left / (bpt ? 17 : 1))
    throw InputError(path, 1,
                     "truncated file: " + std::to_string(n) + " patches announced but only " +
                         std::to_string(lines_left) + " lines");
  std::vector<BezierPatch> patches(std::size_t(n), BezierPatch{});
  if (bpt) {
    for (auto& pa : patches) {
      int ln = 0;
      auto l = in.get(ln, "a patch header '3 3'");
      auto tok = text::split(l);
      if (tok.size() != 2 || tok[0] != "3" || tok[1] != "3")
        throw InputError(path, ln, "expected patch degrees '3 3' (only bicubic patches)");
      for (int k = 0; k < 16; ++k)
        pa.p[k / 4][k % 4] = point_line(in, false);
    }
  } else {
    std::vector<std::array<long long, 16>> idx(patches.size());
    std::vector<int> idx_line(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q) {
      int ln = 0;
      auto tok = text::split(in.get(ln, "a patch's 16 indices"), true);
      if (tok.size() != 16) throw InputError(path, ln, "expected 16 control-point indices");
      for (int k = 0; k < 16; ++k) {
        auto v = text::to_int(tok[std::size_t(k)]);
        if (!v)
          throw InputError(path, ln, "not an index: '" + std::string(tok[std::size_t(k)]) + "'");
        idx[q][std::size_t(k)] = *v;
      }
      idx_line[q] = ln;
    }
    int m_line = 0;
    const long long m = count_line(in, "the control-point count", 100000000, &m_line);
    if (m > lines_left - (long long)in.next)
      throw InputError(path, m_line,
                       "truncated file: " + std::to_string(m) +
                           " control points announced but only " +
                           std::to_string(lines_left - (long long)in.next) + " lines follow");
    std::vector<glm::dvec3> pts(static_cast<std::size_t>(m));
    for (auto& p : pts)
      p = point_line(in, true);
    for (std::size_t q = 0; q < patches.size(); ++q)
      for (int k = 0; k < 16; ++k) {
        long long i = idx[q][std::size_t(k)];
        if (i < 1 || i > m)
          throw InputError(path, idx_line[q],
                           "control-point index " + std::to_string(i) + " out of range 1.." +
                               std::to_string(m));
        patches[q].p[k / 4][k % 4] = pts[std::size_t(i - 1)];
      }
  }
  return patches;
}

namespace {

// Bernstein weights at parameter k/level, computed from t and s = 1 - t = (level-k)/level so that
// the weights at k and at level-k are exact mirror images (shared patch edges match bit for bit).
struct Basis {
  double b[4], d[4]; // values and derivatives
};
Basis basis(int k, int level) {
  const double t = double(k) / double(level), s = double(level - k) / double(level);
  const double ts = t * s;
  Basis r;
  r.b[0] = s * s * s;
  r.b[1] = 3.0 * ts * s;
  r.b[2] = 3.0 * ts * t;
  r.b[3] = t * t * t;
  r.d[0] = -3.0 * s * s;
  r.d[1] = 3.0 * s * s - 6.0 * ts;
  r.d[2] = 6.0 * ts - 3.0 * t * t;
  r.d[3] = 3.0 * t * t;
  return r;
}
Basis basis_at(double t) {
  const double s = 1.0 - t, ts = t * s;
  return {{s * s * s, 3 * ts * s, 3 * ts * t, t * t * t},
          {-3 * s * s, 3 * s * s - 6 * ts, 6 * ts - 3 * t * t, 3 * t * t}};
}

// Sum of w[i] * c[i] in a mirror-symmetric order.
glm::dvec3 comb(const double w[4], const glm::dvec3 c[4]) {
  return (w[0] * c[0] + w[3] * c[3]) + (w[1] * c[1] + w[2] * c[2]);
}

struct Eval {
  glm::dvec3 p, du, dv;
};
Eval evaluate(const BezierPatch& pa, const Basis& bu, const Basis& bv) {
  glm::dvec3 cv[4], cdv[4];
  for (int i = 0; i < 4; ++i) {
    cv[i] = comb(bv.b, pa.p[i]);
    cdv[i] = comb(bv.d, pa.p[i]);
  }
  return {comb(bu.b, cv), comb(bu.d, cv), comb(bu.b, cdv)};
}

} // namespace

bool looks_like_bezier(const std::string& s) {
  const std::string head = s.substr(0, 4096);
  auto lines = split_lines(head);
  std::vector<std::string_view> nonempty;
  for (auto l : lines) {
    l = text::trim(l);
    if (!l.empty()) nonempty.push_back(l);
    if (nonempty.size() == 2) break;
  }
  if (nonempty.size() < 2 || !text::to_int(nonempty[0])) return false;
  // A count, then a line of numbers (a patch's indices): a patch file, whose reader names what is
  // wrong with it (a scene description line starts with a keyword).
  auto tok = text::split(nonempty[1], true);
  return tok.size() >= 2 && text::to_int(tok[0]).has_value();
}

std::shared_ptr<const std::vector<BezierPatch>> read_bezier_file(const std::string& path) {
  static std::mutex mu;
  static std::map<std::string, std::shared_ptr<const std::vector<BezierPatch>>> cache;
  {
    std::lock_guard<std::mutex> lock(mu);
    auto it = cache.find(path);
    if (it != cache.end()) return it->second;
  }
  auto p =
      std::make_shared<const std::vector<BezierPatch>>(parse_bezier(text::read_file(path), path));
  std::lock_guard<std::mutex> lock(mu);
  cache.emplace(path, p);
  return p;
}

LocalMesh tessellate_patches(const std::vector<BezierPatch>& patches, int level) {
  LocalMesh m;
  const std::size_t n1 = std::size_t(level) + 1;
  m.positions.reserve(patches.size() * n1 * n1);
  m.normals.reserve(patches.size() * n1 * n1);
  m.triangles.reserve(patches.size() * std::size_t(level) * std::size_t(level) * 2);
  std::vector<Basis> bs(n1);
  for (int k = 0; k <= level; ++k)
    bs[std::size_t(k)] = basis(k, level);
  for (const auto& pa : patches) {
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (int i = 0; i <= level; ++i)
      for (int j = 0; j <= level; ++j) {
        Eval e = evaluate(pa, bs[std::size_t(i)], bs[std::size_t(j)]);
        glm::dvec3 n = glm::cross(e.dv, e.du); // outward for Newell's data
        double scale = glm::length(e.du) * glm::length(e.dv);
        if (!(glm::length(n) > 1e-9 * scale) || scale == 0) {
          // Degenerate (a collapsed patch edge): take the normal slightly inside the patch.
          const double eps = 1e-3;
          double u = double(i) / level, v = double(j) / level;
          u += u < 0.5 ? eps : -eps;
          v += v < 0.5 ? eps : -eps;
          Eval f = evaluate(pa, basis_at(u), basis_at(v));
          n = glm::cross(f.dv, f.du);
        }
        double len = glm::length(n);
        m.positions.push_back(e.p);
        m.normals.push_back(len > 0 ? n / len : glm::dvec3(0, 0, 1));
      }
    for (int i = 0; i < level; ++i)
      for (int j = 0; j < level; ++j) {
        const std::uint32_t a = base + std::uint32_t(i * (level + 1) + j);
        const std::uint32_t b = a + std::uint32_t(level + 1); // i+1
        // Counter-clockwise around dv x du.
        Triangle t1, t2;
        t1.v[0] = a, t1.v[1] = b + 1, t1.v[2] = b;
        t2.v[0] = a, t2.v[1] = a + 1, t2.v[2] = b + 1;
        m.triangles.push_back(t1);
        m.triangles.push_back(t2);
      }
  }
  return m;
}

} // namespace zc
