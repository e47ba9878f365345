#include "pak/io/text_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pak/error.hpp"

namespace pak {

std::string readTextFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the file (missing or unreadable)");
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read the file");
  return contents.str();
}

}  // namespace pak
