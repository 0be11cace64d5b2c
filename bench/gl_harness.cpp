#include "gl_harness.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <sstream>

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

namespace zc::bench {

namespace {

const char* kVS = "#version 330 core\n"
                  "uniform mat4 view_proj;\n"
                  "layout(location = 0) in vec3 pos; layout(location = 1) in vec3 col;\n"
                  "out vec3 c;\n"
                  "void main() { gl_Position = view_proj * vec4(pos, 1.0); c = col; }\n";
const char* kFS = "#version 330 core\n"
                  "in vec3 c; out vec4 o;\n"
                  "void main() { o = vec4(c, 1.0); }\n";

bool compile(GLuint prog, GLenum type, const char* src, std::string& err) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[512] = {};
    glGetShaderInfoLog(s, sizeof log - 1, nullptr, log);
    err = std::string("shader: ") + log;
    return false;
  }
  glAttachShader(prog, s);
  return true;
}

bool has_ext(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

bool g_cpu_time = false; // set in the child process only

double now_s() {
  if (g_cpu_time) {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

GlResult run_in_child(const GlScene& sc, double min_seconds) {
  GlResult r;
  const char* cext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_ext(cext, "EGL_MESA_platform_surfaceless")) {
    r.error = "EGL_MESA_platform_surfaceless missing";
    return r;
  }
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLDisplay dpy = get_platform_display ? get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                                               EGL_DEFAULT_DISPLAY, nullptr)
                                        : EGL_NO_DISPLAY;
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) {
    r.error = "no surfaceless EGL display";
    return r;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    r.error = "EGL has no desktop OpenGL";
    return r;
  }
  const EGLint ctx_attr[] = {EGL_CONTEXT_MAJOR_VERSION,
                             3,
                             EGL_CONTEXT_MINOR_VERSION,
                             3,
                             EGL_CONTEXT_OPENGL_PROFILE_MASK,
                             EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                             EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctx_attr);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    r.error = "cannot create a surfaceless OpenGL 3.3 core context";
    return r;
  }
  r.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));

  const int w = sc.width, h = sc.height;
  GLuint fbo, rb[2];
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    r.error = "incomplete frame buffer";
    return r;
  }

  GLuint prog = glCreateProgram();
  if (!compile(prog, GL_VERTEX_SHADER, kVS, r.error) ||
      !compile(prog, GL_FRAGMENT_SHADER, kFS, r.error))
    return r;
  glLinkProgram(prog);
  GLint linked = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &linked);
  if (!linked) {
    r.error = "program does not link";
    return r;
  }
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "view_proj"), 1, GL_FALSE, sc.view_proj);

  GLuint vao, buf[3];
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(3, buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sc.position.size() * sizeof(float)), sc.position.data(),
               GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sc.color.size() * sizeof(float)), sc.color.data(),
               GL_STATIC_DRAW);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(sc.index.size() * sizeof(std::uint32_t)),
               sc.index.data(), GL_STATIC_DRAW);

  glViewport(0, 0, w, h);
  glClearColor(0, 0, 0, 1);
  glClearDepth(1.0);
  if (sc.cull_back) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  const GLsizei count = GLsizei(sc.index.size());

  // Untimed: fragments rasterised in one frame (every fragment passes with no depth test).
  GLuint query;
  glGenQueries(1, &query);
  glDisable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 frags = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &frags);
  r.fragments = frags;

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  auto frame = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    glFinish();
  };
  frame(); // warm-up (shader variants, buffer upload)
  std::vector<double> t;
  const double start = now_s();
  while (t.size() < 3 || now_s() - start < min_seconds) {
    const double t0 = now_s();
    frame();
    t.push_back(now_s() - t0);
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  r.seconds = t[t.size() / 2];
  const GLenum e = glGetError();
  r.ok = e == GL_NO_ERROR;
  if (!r.ok) r.error = "GL error " + std::to_string(e);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return r;
}

} // namespace

GlResult gl_time_frame(const GlScene& sc, int lp_threads, double min_seconds, bool cpu_time) {
  GlResult r;
  int fds[2];
  if (pipe(fds) != 0) {
    r.error = "pipe failed";
    return r;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    r.error = "fork failed";
    return r;
  }
  if (pid == 0) { // child: a fresh Mesa context that reads LP_NUM_THREADS at creation
    close(fds[0]);
    setenv("LP_NUM_THREADS", std::to_string(lp_threads).c_str(), 1);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    g_cpu_time = cpu_time;
    const GlResult c = run_in_child(sc, min_seconds);
    std::ostringstream msg;
    msg.precision(17);
    msg << c.ok << '\n'
        << c.seconds << '\n'
        << c.fragments << '\n'
        << c.renderer << '\n'
        << c.error << '\n';
    const std::string s = msg.str();
    const bool sent = write(fds[1], s.data(), s.size()) == ssize_t(s.size());
    _exit(sent ? 0 : 1);
  }
  close(fds[1]);
  std::string in;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;)
    in.append(buf, std::size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  std::istringstream is(in);
  std::string ok, secs, frags;
  if (!std::getline(is, ok) || !std::getline(is, secs) || !std::getline(is, frags) ||
      !std::getline(is, r.renderer) || !std::getline(is, r.error)) {
    r.error = "GL child process failed (status " + std::to_string(status) + ")";
    return r;
  }
  r.ok = ok == "1";
  r.seconds = std::strtod(secs.c_str(), nullptr);
  r.fragments = std::strtoull(frags.c_str(), nullptr, 10);
  return r;
}

} // namespace zc::bench
