#pragma once
// What a glTF material's name says about it, as pipelines name materials ("Fabric_Boucle.001",
// "Sofa Velvet", "Oak_Legs"): a fabric word, a hard material's word, both, or nothing. Rule and
// word lists: docs/design.md §1 ("glTF materials as cloth").
#include <string>
#include <vector>

namespace weft {

struct ClothNameVerdict {
  enum class Kind {
    none,       // no known word
    preset,     // fabric words that all name `preset` ("Velvet.001", "Linen_Cotton")
    generic,    // only generic cloth words ("Fabric", "Upholstery"): cloth, the weave unsaid
    hard,       // only hard-material words ("Oak", "Chrome_Leg"): not cloth
    ambiguous,  // words that disagree ("Velvet_Satin", "Wood_Fabric")
  };
  Kind kind = Kind::none;
  std::string preset;               // for Kind::preset
  std::vector<std::string> words;   // the known words found, lower case, in order, for the log
};

// The name's words: split at anything but letters and digits, at a lower-to-upper case step
// ("SofaVelvet") and between letters and digits, in lower case; digits alone (Blender's ".001")
// are dropped. Bytes above ASCII count as letters, so "Bouclé" stays one word.
std::vector<std::string> material_name_words(const std::string& name);

// The verdict on a material name. A word matches a keyword exactly or with a plural "s".
ClothNameVerdict cloth_name_verdict(const std::string& name);

}  // namespace weft
