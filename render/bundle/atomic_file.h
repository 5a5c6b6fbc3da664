#pragma once
// Replaces a file so that a power cut leaves either the old or the new contents, never a mix:
// write a temporary file beside it, fsync it, rename it over the target, fsync the directory.
#include <cstddef>
#include <filesystem>
#include <span>

namespace weft::bundle {

// Throws std::system_error naming the file and the step that failed; the temporary is removed.
void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> bytes);

}  // namespace weft::bundle
