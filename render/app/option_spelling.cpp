#include "app/option_spelling.h"

#include <memory>
#include <string>

namespace weft {

namespace {

class FirstNameFormatter : public CLI::Formatter {
public:
  std::string make_option_name(const CLI::Option* opt, bool is_positional) const override {
    if (is_positional) return CLI::Formatter::make_option_name(opt, is_positional);
    std::string names;
    for (const auto& s : opt->get_snames()) names += (names.empty() ? "-" : ",-") + s;
    if (!opt->get_lnames().empty()) names += (names.empty() ? "--" : ",--") + opt->get_lnames().front();
    return names;
  }
};

}  // namespace

void show_first_names_only(CLI::App& app) { app.formatter(std::make_shared<FirstNameFormatter>()); }

CLI::Option* old_spelling(CLI::Option* option) { return option->group(""); }

}  // namespace weft
