#include "output_files.hpp"

#include <filesystem>
#include <system_error>

#include "pak/error.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak::cli {

void createFolder(const std::string& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw InputError(folder, "cannot create the folder: " + ec.message());
}

void writePngPreview(const Drawing& drawing, const std::string& path, int width) {
  if (path.empty()) return;
  PngOptions png;
  png.width = width;
  writePngFile(drawing, path, png);
}

}  // namespace pak::cli
