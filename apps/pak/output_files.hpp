#pragma once
// Writing what a run asked for, with the checks every command needs.
#include <string>
#include <vector>

#include "pak/geom/scene.hpp"
#include "pak/io/drawing.hpp"

namespace pak::cli {

// A file the run will write: the option that names it, and its path (empty: not asked for).
struct PlannedOutput {
  const char* option;
  std::string path;
};

// Before any work, so that a long run never ends in "cannot write": each output's folder exists
// and is writable, no output is one of `inputs` (the files the run reads), and no two outputs
// are the same file. Throws InputError naming the path.
// `files`, then the file of each element of `libraries`: what checkOutputsBeforeTheRun protects.
std::vector<std::string> inputFiles(std::vector<std::string> files, const std::vector<const Library*>& libraries);
void checkOutputsBeforeTheRun(const std::vector<PlannedOutput>& outputs, const std::vector<std::string>& inputs);

// An output folder the run will create (or fill): not an existing file, and its nearest
// existing ancestor a writable folder. Throws InputError naming it.
void checkOutputFolder(const std::string& folder);

// --png-width (or `option`), checked before the run rather than when the PNG is drawn.
void checkPngWidth(int width, const char* option = "--png-width");

// Creates `folder` and its parents, or throws InputError naming it.
void createFolder(const std::string& folder);

// The PNG preview, `width` pixels wide, when `path` is not empty.
void writePngPreview(const Drawing& drawing, const std::string& path, int width);

}  // namespace pak::cli
