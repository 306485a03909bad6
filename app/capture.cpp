#include "app/capture.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <utility>

#include <fcntl.h>
#include <png.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gl/draw.h"

extern char** environ;

namespace csm {

CaptureTarget::CaptureTarget(int width, int height)
    : width_(width), height_(height), color_(gl::TextureFormat::Rgba8, width, height) {
  framebuffer_.attach(gl::Attachment::Color0, color_).setDrawBuffers({gl::Attachment::Color0});
}

std::vector<std::uint8_t> CaptureTarget::readRgb() const {
  std::vector<std::uint8_t> bottomUp =
      framebuffer_.read<std::uint8_t>(gl::Attachment::Color0, {0, 0, width_, height_},
                                      gl::PixelFormat::Rgb, gl::PixelType::UnsignedByte, 3);
  // GL's rows run bottom to top; images run top to bottom.
  std::vector<std::uint8_t> rgb(bottomUp.size());
  const std::size_t row = std::size_t(width_) * 3;
  for (int y = 0; y < height_; ++y)
    std::memcpy(&rgb[std::size_t(y) * row], &bottomUp[std::size_t(height_ - 1 - y) * row], row);
  return rgb;
}

void CaptureTarget::waitForGpu() {
  gl::finish();
}

namespace {

struct PngWriteContext {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWriteContext() { png_destroy_write_struct(&png, &info); }
};

struct File {
  FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

// The PNG into `tmp`, closed; false with why.
bool writePngFile(const std::string& tmp, int width, int height,
                  const std::vector<std::uint8_t>& rgb,
                  const std::function<bool(std::string)>& fail) {
  File file;
  file.f = std::fopen(tmp.c_str(), "wb");
  if (!file.f) return fail(std::string("cannot write: ") + std::strerror(errno));
  PngWriteContext ctx;
  ctx.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!ctx.png) return fail("libpng failed to start");
  ctx.info = png_create_info_struct(ctx.png);
  if (!ctx.info) return fail("libpng failed to start");
  if (setjmp(png_jmpbuf(ctx.png))) return fail("libpng failed while writing");
  png_init_io(ctx.png, file.f);
  // Fast compression: frames are written every step of a headless run.
  png_set_compression_level(ctx.png, 3);
  png_set_IHDR(ctx.png, ctx.info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(ctx.png, ctx.info);
  for (int y = 0; y < height; ++y)
    png_write_row(ctx.png, const_cast<png_bytep>(&rgb[std::size_t(y) * width * 3]));
  png_write_end(ctx.png, nullptr);
  FILE* f = std::exchange(file.f, nullptr);
  if (std::fflush(f) != 0 || std::fclose(f) != 0)
    return fail(std::string("cannot write: ") + std::strerror(errno));
  return true;
}

}  // namespace

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb,
              std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  if (width <= 0 || height <= 0 || rgb.size() != std::size_t(width) * height * 3)
    return fail("internal error: image size and pixel count disagree");
  // Written beside the name, then renamed over it: a reader (a farm's join, a rerun chunk) never
  // sees half a frame, and a failed write leaves the old one.
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  if (!writePngFile(tmp, width, height, rgb, fail)) {
    std::remove(tmp.c_str());
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return fail("cannot rename the written file into place: " + why);
  }
  return true;
}

std::string findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::string all = path;
  std::size_t start = 0;
  while (start <= all.size()) {
    std::size_t end = all.find(':', start);
    if (end == std::string::npos) end = all.size();
    const std::string dir = end > start ? all.substr(start, end - start) : ".";
    const std::string candidate = dir + "/" + name;
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return {};
}

std::unique_ptr<VideoPipe> VideoPipe::open(const std::string& path, int width, int height,
                                           double fps, std::string* error) {
  const std::string ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty()) {
    if (error)
      *error =
          "--video needs ffmpeg, which is not installed (not found on PATH); install it "
          "(e.g. apt install ffmpeg) or write PNG frames with --out DIR";
    return nullptr;
  }
  int fds[2];
  if (::pipe(fds) != 0) {
    if (error) *error = std::string("cannot make a pipe for ffmpeg: ") + std::strerror(errno);
    return nullptr;
  }
  // A broken pipe (ffmpeg quit) must be an error from write(), not a silent exit.
  std::signal(SIGPIPE, SIG_IGN);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps > 0 ? fps : 60.0);
  // yuv420p needs even sides; the scale filter rounds down where they are odd.
  std::vector<std::string> args = {
      ffmpeg,     "-y",       "-loglevel", "error",
      "-f",       "rawvideo", "-pix_fmt",  "rgb24",
      "-s",       size,       "-r",        rate,
      "-i",       "-",        "-vf",       "scale=trunc(iw/2)*2:trunc(ih/2)*2",
      "-pix_fmt", "yuv420p",  "-c:v",      "libx264",
      "-crf",     "18",       path};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (rc != 0) {
    ::close(fds[1]);
    if (error) *error = "cannot start " + ffmpeg + ": " + std::strerror(rc);
    return nullptr;
  }
  std::unique_ptr<VideoPipe> v(new VideoPipe());
  v->fd_ = fds[1];
  v->pid_ = pid;
  v->path_ = path;
  return v;
}

VideoPipe::~VideoPipe() {
  close(nullptr);
}

bool VideoPipe::write(const std::vector<std::uint8_t>& rgb) {
  if (fd_ < 0) return false;
  std::size_t done = 0;
  while (done < rgb.size()) {
    const ssize_t n = ::write(fd_, rgb.data() + done, rgb.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += std::size_t(n);
  }
  return true;
}

bool VideoPipe::close(std::string* error) {
  if (fd_ < 0) return true;
  ::close(fd_);
  fd_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  if (error)
    *error = path_ + ": ffmpeg failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  return false;
}

}  // namespace csm
