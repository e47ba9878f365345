#pragma once
// Writing what a run asked for, with the checks every command needs.
#include <string>

#include "pak/io/drawing.hpp"

namespace pak::cli {

// Creates `folder` and its parents, or throws InputError naming it.
void createFolder(const std::string& folder);

// The PNG preview, `width` pixels wide, when `path` is not empty.
void writePngPreview(const Drawing& drawing, const std::string& path, int width);

}  // namespace pak::cli
