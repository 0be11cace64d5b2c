#include "gl_harness.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

namespace zc::bench {

namespace {

const char* kVS = "#version 300 es\n"
                  "in vec4 pos; in vec3 col; out vec3 c;\n"
                  "void main() { gl_Position = pos; c = col; }\n";
const char* kFS = "#version 300 es\nprecision mediump float;\n"
                  "in vec3 c; out vec4 o;\nvoid main() { o = vec4(c, 1.0); }\n";

GLuint shader(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  return s;
}

GlResult run_in_child(const std::vector<ProjectedVertex>& pv, const std::vector<std::uint32_t>& idx,
                      int w, int h, double min_seconds) {
  GlResult r;
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLDisplay dpy = get_platform_display ? get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                                               EGL_DEFAULT_DISPLAY, nullptr)
                                        : EGL_NO_DISPLAY;
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) {
    r.error = "no surfaceless EGL display";
    return r;
  }
  eglBindAPI(EGL_OPENGL_ES_API);
  const EGLint cfg_attr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
  EGLConfig cfg;
  EGLint n = 0;
  eglChooseConfig(dpy, cfg_attr, &cfg, 1, &n);
  const EGLint ctx_attr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, n ? cfg : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctx_attr);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    r.error = "cannot create a GLES3 context";
    return r;
  }
  r.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
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
  glAttachShader(prog, shader(GL_VERTEX_SHADER, kVS));
  glAttachShader(prog, shader(GL_FRAGMENT_SHADER, kFS));
  glBindAttribLocation(prog, 0, "pos");
  glBindAttribLocation(prog, 1, "col");
  glLinkProgram(prog);
  glUseProgram(prog);
  GLuint buf[2];
  glGenBuffers(2, buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(pv.size() * sizeof(ProjectedVertex)), pv.data(),
               GL_STATIC_DRAW);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(ProjectedVertex), nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(ProjectedVertex),
                        reinterpret_cast<void*>(offsetof(ProjectedVertex, light)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
  glViewport(0, 0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  auto frame = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
  };
  frame(); // warm-up (shader compilation, buffer upload)
  std::vector<double> t;
  const auto start = std::chrono::steady_clock::now();
  while (t.size() < 3 ||
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
             min_seconds) {
    const auto t0 = std::chrono::steady_clock::now();
    frame();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  r.seconds = t[t.size() / 2];
  r.ok = glGetError() == GL_NO_ERROR;
  if (!r.ok) r.error = "GL error";
  eglTerminate(dpy);
  return r;
}

} // namespace

GlResult gl_time_frame(const std::vector<ProjectedVertex>& pv,
                       const std::vector<std::uint32_t>& idx, int w, int h, int lp_threads,
                       double min_seconds) {
  int fds[2];
  GlResult r;
  if (pipe(fds) != 0) return r;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    setenv("LP_NUM_THREADS", std::to_string(lp_threads).c_str(), 1);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    setenv("EGL_PLATFORM", "surfaceless", 1);
    GlResult c = run_in_child(pv, idx, w, h, min_seconds);
    std::string msg = std::to_string(c.ok) + "\n" + std::to_string(c.seconds) + "\n" + c.renderer +
                      "\n" + c.error + "\n";
    if (write(fds[1], msg.data(), msg.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string in;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;)
    in.append(buf, std::size_t(n));
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  std::vector<std::string> lines;
  std::size_t p = 0;
  for (std::size_t q; (q = in.find('\n', p)) != std::string::npos; p = q + 1)
    lines.push_back(in.substr(p, q - p));
  if (lines.size() < 4) {
    r.error = "GL child process failed";
    return r;
  }
  r.ok = lines[0] == "1";
  r.seconds = std::stod(lines[1]);
  r.renderer = lines[2];
  r.error = lines[3];
  return r;
}

} // namespace zc::bench
