#pragma once
// What the readers skipped in the inputs (unsupported SVG, open paths, shapes that paint
// nothing), printed by every command that packs, as `pak inspect` lists it.
#include <initializer_list>

#include "pak/geom/scene.hpp"

namespace pak::cli {

// The scene's warnings, then those of every element of `libraries` and of the scene's own
// container libraries, each once, as "pak: warning: <where>: <message>" on stderr.
void printInputWarnings(const Scene& scene, std::initializer_list<const Library*> libraries);

}  // namespace pak::cli
