#pragma once
// What the readers skipped in the inputs (unsupported SVG, open paths, shapes that paint
// nothing), printed by every command that packs, as `pak inspect` lists it.
#include <initializer_list>
#include <vector>

#include "pak/io/scene_loader.hpp"
#include "pak/io/warning.hpp"

namespace pak::cli {

// The scene's warnings (its container libraries' included), then those of every element of
// `elements`, each once, as "pak: warning: <where>: <message>" on stderr.
void printInputWarnings(const std::vector<Warning>& sceneWarnings,
                        std::initializer_list<const std::vector<LoadedElement>*> elements);

}  // namespace pak::cli
