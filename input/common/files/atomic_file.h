#pragma once
// Replaces a file so that a power cut leaves either the old or the new contents, never a mix:
// write a temporary file beside it, fsync it, rename it over the target, fsync the directory.
// Every file the product writes goes through here: bundles and their last-good copy, knob state,
// SG sets, EXR and PNG images (frames, screenshots, map previews), cached references, the bench's
// reports and chart.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace weft {

// Throws std::system_error naming the file and the step that failed; the temporary is removed.
void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> bytes);
void write_file_atomically(const std::filesystem::path& target, std::string_view text);
// For libraries that write only to a path (OpenEXR, libpng): `write` fills the temporary at the
// path it is given (what it throws passes through, the temporary removed); then as above.
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace weft
