#pragma once
// Replaces a file so that a power cut leaves either the old or the new contents, never a mix:
// write a temporary file beside it, fsync it, rename it over the target, fsync the directory.
// Every file the product keeps (bundles and their last-good copy, knob state, SG sets, cached
// references) is written through here.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string_view>

namespace weft {

// Throws std::system_error naming the file and the step that failed; the temporary is removed.
void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> bytes);
void write_file_atomically(const std::filesystem::path& target, std::string_view text);

}  // namespace weft
