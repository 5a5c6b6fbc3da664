#include "scene/gltf_cloth_names.h"

#include <algorithm>
#include <array>
#include <set>
#include <string_view>

namespace weft {

namespace {

struct Keyword {
  std::string_view word;
  std::string_view preset;  // empty: a generic cloth word
};

// A fabric word names the preset whose weave it is: the plain weaves (linen, cotton, wool, bouclé
// and tweed are plain or near-plain weaves of matte yarn) are linen_plain; satin and charmeuse the
// satin; silk the crêpe de chine (the silk a shop sells by the metre, silk_shot's two colours
// being a special case); a pile velvet; a sheer voile.
constexpr std::array kFabricWords{
    Keyword{"velvet", "velvet"},
    Keyword{"velour", "velvet"},
    Keyword{"satin", "polyester_satin_charmeuse"},
    Keyword{"charmeuse", "polyester_satin_charmeuse"},
    Keyword{"silk", "silk_crepe_de_chine"},
    Keyword{"crepe", "silk_crepe_de_chine"},
    Keyword{"cr\xc3\xaape", "silk_crepe_de_chine"},
    Keyword{"linen", "linen_plain"},
    Keyword{"cotton", "linen_plain"},
    Keyword{"wool", "linen_plain"},
    Keyword{"boucle", "linen_plain"},
    Keyword{"boucl\xc3\xa9", "linen_plain"},
    Keyword{"tweed", "linen_plain"},
    Keyword{"canvas", "linen_plain"},
    Keyword{"voile", "polyester_voile"},
    Keyword{"sheer", "polyester_voile"},
    Keyword{"fabric", ""},
    Keyword{"cloth", ""},
    Keyword{"textile", ""},
    Keyword{"upholstery", ""},
    Keyword{"curtain", ""},
};

// Words for the parts of furniture that are not cloth: a product's legs, frame finishes and trims.
constexpr std::array<std::string_view, 27> kHardWords{
    "wood",  "wooden", "oak",       "walnut",   "beech",    "birch",   "pine",  "teak",    "maple",
    "mahogany", "metal", "metallic", "chrome",  "steel",    "brass",   "iron",  "aluminium", "aluminum",
    "plastic", "glass", "leather",  "marble",  "stone",    "rubber",  "leg",   "foot",    "feet",
};

bool matches(const std::string& word, std::string_view keyword) {
  if (word == keyword) return true;
  return word.size() == keyword.size() + 1 && word.back() == 's' && std::string_view(word).substr(0, keyword.size()) == keyword;
}

enum class Char { other, lower, upper, digit };

Char kind_of(unsigned char c) {
  if (c >= 'a' && c <= 'z') return Char::lower;
  if (c >= 'A' && c <= 'Z') return Char::upper;
  if (c >= '0' && c <= '9') return Char::digit;
  if (c >= 0x80) return Char::lower;  // a UTF-8 letter's byte: no case step is read inside it
  return Char::other;
}

}  // namespace

std::vector<std::string> material_name_words(const std::string& name) {
  std::vector<std::string> words;
  std::string word;
  const auto flush = [&] {
    if (!word.empty() && !std::all_of(word.begin(), word.end(), [](unsigned char c) { return c >= '0' && c <= '9'; }))
      words.push_back(word);
    word.clear();
  };
  Char previous = Char::other;
  for (size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    const Char k = kind_of(c);
    if (k == Char::other) {
      flush();
      previous = k;
      continue;
    }
    const bool next_lower = i + 1 < name.size() && kind_of(static_cast<unsigned char>(name[i + 1])) == Char::lower;
    const bool step = (previous == Char::lower && k == Char::upper) ||                      // "sofaVelvet"
                      (previous == Char::upper && k == Char::upper && next_lower) ||        // "SOFAVelvet"
                      (previous != Char::other && (previous == Char::digit) != (k == Char::digit));  // "velvet2"
    if (step) flush();
    word.push_back(k == Char::upper ? static_cast<char>(c - 'A' + 'a') : static_cast<char>(c));
    previous = k;
  }
  flush();
  return words;
}

ClothNameVerdict cloth_name_verdict(const std::string& name) {
  ClothNameVerdict v;
  std::set<std::string> presets;
  bool generic = false, hard = false;
  for (const std::string& word : material_name_words(name)) {
    bool known = false;
    for (const Keyword& k : kFabricWords)
      if (matches(word, k.word)) {
        known = true;
        if (k.preset.empty())
          generic = true;
        else
          presets.insert(std::string(k.preset));
      }
    for (std::string_view h : kHardWords)
      if (matches(word, h)) known = hard = true;
    if (known) v.words.push_back(word);
  }
  using Kind = ClothNameVerdict::Kind;
  if (hard && (generic || !presets.empty()))
    v.kind = Kind::ambiguous;
  else if (hard)
    v.kind = Kind::hard;
  else if (presets.size() > 1)
    v.kind = Kind::ambiguous;
  else if (presets.size() == 1) {
    v.kind = Kind::preset;
    v.preset = *presets.begin();
  } else if (generic)
    v.kind = Kind::generic;
  return v;
}

}  // namespace weft
