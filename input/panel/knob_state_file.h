#pragma once
// The knob positions on disk, so a kiosk that loses power comes back as the shopper left it.
// Written atomically (temporary file, fsync, rename, fsync of the directory); read back at
// boot, where anything wrong (missing, truncated, bad JSON, checksum mismatch, unknown preset,
// absurd numbers) falls back to the preset and says why.
//
// Format (JSON): {"format":"weft-knobs","version":1,"preset":"linen_plain","selection":"both",
//   "threads":[{"hue_steps":0,"brightness_steps":0,"gloss_steps":0},{…}],"env_steps":0,
//   ["colourway":"Ocean",] "checksum":"<FNV-1a 64 of the same object without this member, compact dump, hex>"}
// "colourway" names the colourway worn when the bundle has colourways; a file without it wears
// the first.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "panel/knob_mapping.h"

namespace weft::input {

class KnobStateError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// `colourways`: the bundle's colourway names (KnobMapper::colourway_names), empty without any.
std::string knob_state_text(const KnobPositions& positions, const std::vector<PresetLook>& presets,
                            const std::vector<std::string>& colourways = {});
// Throws KnobStateError saying what is wrong.
KnobPositions parse_knob_state(const std::string& text, const std::vector<PresetLook>& presets,
                               const std::vector<std::string>& colourways = {});

// Replaces `file` with `text` so that after a crash or power cut it holds either the old or the
// new content, never a mix (files/atomic_file.h). Returns false and `why` on failure.
bool write_file_atomically(const std::filesystem::path& file, const std::string& text, std::string& why);

struct RestoredKnobs {
  KnobPositions positions;
  bool from_file = false;
  bool unusable = false;  // a file was there but could not be read as knob state
  std::string message;  // operator-readable: what was restored, or why the preset was used
};
RestoredKnobs restore_knob_state(const std::filesystem::path& file, const std::vector<PresetLook>& presets,
                                 uint32_t default_preset, const std::vector<std::string>& colourways = {});

}  // namespace weft::input
