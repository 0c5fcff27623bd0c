// The file operations of a results folder (POSIX). Failures throw
// BatchError naming the path.
#pragma once

#include <cstddef>
#include <string>

#include "app/experiment/BatchError.hpp"

namespace simswift::experiment {

bool exists(const std::string& path);
void makeDir(const std::string& path);   // one level; an existing folder is fine
void makeDirs(const std::string& path);  // every level of the path
std::string readFile(const std::string& path);
// Written to a temporary name (path.tmp<pid>), flushed, then renamed: a
// reader sees the whole file or none (kill -9 included).
void writeAtomic(const std::string& path, const std::string& text);
// The last max_chars of a text file ("..." in front if cut), without
// trailing newlines; empty if there is no such file.
std::string fileTail(const std::string& path, size_t max_chars);

}  // namespace simswift::experiment
