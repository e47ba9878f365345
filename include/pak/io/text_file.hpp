#pragma once
// Reads a whole input file, with the errors every reader reports the same way.
#include <string>

namespace pak {

// Throws InputError naming the path if it is a folder, missing, unreadable or fails mid-read.
std::string readTextFile(const std::string& path);

}  // namespace pak
