#include "output_files.hpp"

#include <filesystem>
#include <system_error>

#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak::cli {

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
