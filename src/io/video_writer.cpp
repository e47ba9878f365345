// MP4 and WebM through the `ffmpeg` program, if installed: Pak links no video codec. Raw RGBA
// frames go down a pipe into ffmpeg, which writes a temporary file beside the target; the
// rename happens only when ffmpeg succeeded, so a failed encode leaves nothing behind.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/animation_frames.hpp"
#include "io/drawing_raster.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/atomic_file.hpp"

extern char** environ;

namespace pak {
namespace {

const char* const kMissing = "ffmpeg not found; install it for MP4/WebM output";

// Runs `arguments` (found on PATH) with stdin from `input` (-1: /dev/null) and stderr into
// `log` (-1: /dev/null). Returns the child's pid, or -1 with errno set.
pid_t spawn(const std::vector<std::string>& arguments, int input, int log) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (input >= 0)
    posix_spawn_file_actions_adddup2(&actions, input, STDIN_FILENO);
  else
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (log >= 0)
    posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
  else
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    errno = error;
    return -1;
  }
  return pid;
}

// The exit status, or -1 when the child did not exit normally.
int waitFor(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The codec arguments for the target's extension; throws InputError for any other extension.
std::vector<std::string> codecArguments(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".mp4")  // H.264 in 4:2:0, which every player decodes
    return {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-preset", "medium", "-movflags", "+faststart",
            "-f", "mp4"};
  if (extension == ".webm")
    return {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", "30", "-b:v", "0", "-f", "webm"};
  throw InputError(path, "unknown video format '" + extension + "' (use .mp4 or .webm)");
}

// The last non-empty line ffmpeg wrote to its log, for the error message.
std::string lastLine(std::FILE* log) {
  std::string text;
  std::rewind(log);
  char buffer[4096];
  std::size_t read;
  while ((read = std::fread(buffer, 1, sizeof buffer, log)) > 0) text.append(buffer, read);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  std::size_t start = text.find_last_of('\n');
  return start == std::string::npos ? text : text.substr(start + 1);
}

// A broken pipe (ffmpeg quit early) must be an error return, not a SIGPIPE that kills the
// program: block the signal on this thread while writing, then discard it if one came.
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &previous_);
  }
  ~SigpipeBlock() {
    sigset_t pending;
    sigpending(&pending);
    if (sigismember(&pending, SIGPIPE) && !sigismember(&previous_, SIGPIPE)) {
      timespec zero{0, 0};
      sigtimedwait(&pipe_, nullptr, &zero);
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }

 private:
  sigset_t pipe_, previous_;
};

bool writeAll(int descriptor, const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    ssize_t written = ::write(descriptor, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

}  // namespace

bool videoEncoderAvailable() {
  pid_t pid = spawn({"ffmpeg", "-hide_banner", "-version"}, -1, -1);
  return pid > 0 && waitFor(pid) == 0;
}

void checkVideoTarget(const std::string& path) {
  codecArguments(path);
  if (!videoEncoderAvailable()) throw InputError(path, kMissing);
}

void writeVideo(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& options) {
  std::vector<std::string> codec = codecArguments(path);
  animation_frames::checkFrames(frames, options, path);
  AnimationOutputOptions opaque = options;
  if (!opaque.background) opaque.background = Color{255, 255, 255, 1.0};  // video has no alpha
  // Even sizes: 4:2:0 chroma has one sample per 2 x 2 pixels.
  const PngOptions png = animation_frames::rasterOptions(frames, opaque, path, true);
  const std::string temporary = temporaryPathFor(path);
  if (!videoEncoderAvailable()) throw InputError(path, kMissing);

  // Frames per second as a fraction, exact for any duration to the millisecond.
  const long long milliseconds = std::max(1LL, std::llround(options.duration * 1000.0));
  const std::string rate = std::to_string(static_cast<long long>(frames.size()) * 1000) + "/" + std::to_string(milliseconds);
  std::vector<std::string> arguments = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                        "-pix_fmt", "rgba", "-s", std::to_string(png.width) + "x" + std::to_string(png.height),
                                        "-r", rate, "-i", "-", "-an"};
  arguments.insert(arguments.end(), codec.begin(), codec.end());
  arguments.push_back(temporary);

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> log(std::tmpfile(), std::fclose);
  int pipeEnds[2];
  if (::pipe2(pipeEnds, O_CLOEXEC) != 0) throw InputError(path, std::string("cannot start ffmpeg: ") + std::strerror(errno));
  pid_t pid = spawn(arguments, pipeEnds[0], log ? fileno(log.get()) : -1);
  int spawnError = errno;
  ::close(pipeEnds[0]);
  if (pid < 0) {
    ::close(pipeEnds[1]);
    throw InputError(path, spawnError == ENOENT ? kMissing : std::string("cannot start ffmpeg: ") + std::strerror(spawnError));
  }

  // Feed the frames; whatever happens, close the pipe and wait, so no child is left behind.
  bool fed = true;
  std::optional<InputError> renderError;  // a frame that failed to render
  {
    SigpipeBlock block;
    try {
      for (std::size_t i = 0; i < frames.size() && fed; ++i) {
        RgbaImage image = raster::toRgba(raster::renderSurface(frames[i], png, path).get());
        fed = writeAll(pipeEnds[1], image.rgba.data(), image.rgba.size());
      }
    } catch (const InputError& error) {
      renderError = error;
    } catch (const std::exception& error) {
      renderError = InputError(path, error.what());
    }
    ::close(pipeEnds[1]);
  }
  int status = waitFor(pid);
  if (renderError || !fed || status != 0) {
    ::unlink(temporary.c_str());
    if (renderError) throw *renderError;
    std::string detail = log ? lastLine(log.get()) : std::string();
    throw InputError(path, "ffmpeg failed" + (detail.empty() ? std::string() : ": " + detail));
  }
  finishTemporary(temporary, path);
}

}  // namespace pak
