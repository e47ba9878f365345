#include "output_files.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak::cli {

namespace {

// Whether two paths name one file, whether or not it exists yet.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec)) return std::filesystem::equivalent(a, b, ec);
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, ec);
  if (ec) return false;
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

}  // namespace

std::vector<std::string> inputFiles(std::vector<std::string> files, const std::vector<const Library*>& libraries) {
  for (const Library* library : libraries)
    for (const ElementArt& element : *library) files.push_back(element.source);
  return files;
}

void checkOutputsBeforeTheRun(const std::vector<PlannedOutput>& outputs, const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const PlannedOutput& out = outputs[i];
    if (out.path.empty()) continue;
    checkOutputPath(out.path);
    for (const std::string& input : inputs)
      if (!input.empty() && sameFile(out.path, input))
        throw InputError(out.path, std::string(out.option) + " would overwrite an input of this run; write it elsewhere");
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && sameFile(out.path, outputs[j].path))
        throw InputError(out.path, std::string("given to both ") + outputs[j].option + " and " + out.option +
                                       "; each output needs its own file");
  }
}

void checkOutputFolder(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw InputError(folder, "cannot write the output folder: a file of that name exists");
  fs::path existing = fs::absolute(folder, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError(folder, "cannot create the output folder: '" + existing.string() + "' is not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw InputError(folder, "cannot write into '" + existing.string() + "'");
}

void checkPngWidth(int width, const char* option) {
  if (width < 1 || width > kMaxPngPixels)
    throw InputError(option, "must be 1 to " + std::to_string(kMaxPngPixels) + " pixels, got " + std::to_string(width));
}

void createFolder(const std::string& folder) {
  std::error_code ec;
  const bool created = std::filesystem::create_directories(folder, ec);
  if (ec) throw InputError(folder, "cannot create the folder: " + ec.message());
  if (created) listCreatedFolder(folder);  // a second Ctrl-C removes it if it is still empty
}

void writePngPreview(const Drawing& drawing, const std::string& path, int width) {
  if (path.empty()) return;
  PngOptions png;
  png.width = width;
  writePngFile(drawing, path, png);
}

}  // namespace pak::cli
