#pragma once
// Reads an AnimationPak animation file (JSON, format in docs/animation-format.md). Element paths
// are resolved against the file's folder. Throws InputError naming the file and the field
// ("anim.json: elements[2].rotation[1]: t must be within [0, 1]") for anything malformed.
#include <string>

#include "pak/animation/animation_script.hpp"

namespace pak {

AnimationScript readAnimationScript(const std::string& path);
// The same from text; `where` names it in errors and `folder` resolves element paths.
AnimationScript parseAnimationScript(const std::string& json, const std::string& where, const std::string& folder);

}  // namespace pak
