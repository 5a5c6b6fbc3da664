// One spelling per option (render/app/option_spelling.h): every old spelling still parses, into the
// same option as its new spelling (so the same variable, through the same checks), or for one that
// sets part of a new option (--size W H of --width, --height) into the same values; help lists only
// the new spelling. The commands are compiled in from their own sources and parsed, not run, except
// the kiosk's frame size, which is checked on the picture `weft run` writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/option_spelling.h"
#include "support/small_bundle.h"

namespace weft {
namespace {

// Every subcommand of weft and weft-offline on one app. The actions hold the variables the
// options write, so they live as long as the app.
struct WeftApp : CLI::App {
  WeftApp() : CLI::App("weft") {
    show_first_names_only(*this);
    for (auto add : {add_eval_command, add_render_command, add_fit_command, add_panel_command, add_bake_tables_command,
                     add_probe_command, add_bake_command, add_run_command, add_bench_command, add_bundle_command})
      actions.push_back(add(*this));
  }
  std::vector<CommandAction> actions;
};

std::unique_ptr<WeftApp> weft_app() { return std::make_unique<WeftApp>(); }

// What each command needs besides the option under test.
std::vector<std::string> required(const std::string& command) {
  if (command == "bake") return {"--scene", "swatch", "--out", "x.weft"};
  if (command == "render") return {"--out", "x.exr"};
  if (command == "fit") return {"studio"};
  if (command == "run") return {"--bundle", "x.weft"};
  return {};
}

// Parses `weft COMMAND ARGS` and returns the subcommand (owned by `app`).
CLI::App* parse(CLI::App& app, const std::string& command, std::vector<std::string> args) {
  std::vector<std::string> argv = required(command);
  argv.insert(argv.begin(), command);
  argv.insert(argv.end(), args.begin(), args.end());
  std::reverse(argv.begin(), argv.end());  // CLI11 takes a vector in reverse order
  app.parse(argv);
  return app.get_subcommand(command);
}

struct Renamed {
  const char* command;
  const char* old_name;
  const char* new_name;
  std::vector<std::string> values;
};

const std::vector<Renamed> kRenamed = {
    {"bake", "--fit-sgs", "--sg-count", {"12"}},
    {"bake", "--samples", "--tangent-samples", {"2", "3"}},
    {"bake", "--grid", "--table-grid", {"16"}},
    {"bake-tables", "--samples", "--tangent-samples", {"2,3"}},
    {"bake-tables", "--levels", "--lambda-levels", {"5"}},
    {"bench", "--cache", "--reference-cache", {"refs"}},
    {"bench", "--envs", "--maps", {"studio,city@90"}},
    {"bench", "--bake-grid", "--table-grid", {"24"}},
    {"fit", "--count", "--sg-count", {"6"}},
    {"panel", "--config", "--panel-config", {"panel.json"}},
    {"panel", "--speed", "--sim-speed", {"4"}},
    {"probe", "--size", "--width", {"800"}},
    {"render", "--env", "--map", {"studio@90"}},
};

struct Split {
  const char* command;
  std::vector<std::string> old_args, new_args;
  std::vector<const char*> new_names;
};

const std::vector<Split> kSplit = {
    {"run", {"--size", "320", "240"}, {"--width", "320", "--height", "240"}, {"--width", "--height"}},
    {"bake", {"--choose-size", "80", "60"}, {"--choose-width", "80", "--choose-height", "60"},
     {"--choose-width", "--choose-height"}},
};

// The values every option given on the command line took, in the options' order.
std::vector<std::string> given_values(const CLI::App& sub) {
  std::vector<std::string> out;
  for (const CLI::Option* o : sub.get_options())
    if (o->count() > 0 && o->get_name() != "--help")
      for (const auto& r : o->results()) out.push_back(r);
  return out;
}

bool lists(const std::string& help, const std::string& name) {
  return std::regex_search(help, std::regex("(^|[^A-Za-z0-9-])" + name + "([^A-Za-z0-9-]|$)"));
}

TEST(OptionSpelling, AnOldNameIsTheSameOptionAsItsNewName) {
  for (const auto& r : kRenamed) {
    SCOPED_TRACE(std::string(r.command) + " " + r.old_name);
    std::vector<std::string> old_args{r.old_name}, new_args{r.new_name};
    old_args.insert(old_args.end(), r.values.begin(), r.values.end());
    new_args.insert(new_args.end(), r.values.begin(), r.values.end());
    const auto a = weft_app(), b = weft_app();
    const CLI::App* old_sub = parse(*a, r.command, old_args);
    const CLI::App* new_sub = parse(*b, r.command, new_args);
    ASSERT_EQ(old_sub->get_option(r.old_name), old_sub->get_option(r.new_name));
    EXPECT_EQ(old_sub->get_option(r.new_name)->count(), new_sub->get_option(r.new_name)->count());
    EXPECT_EQ(old_sub->get_option(r.new_name)->results(), new_sub->get_option(r.new_name)->results());
    EXPECT_EQ(given_values(*old_sub), given_values(*new_sub));
  }
}

TEST(OptionSpelling, AnOldNameForPartOfNewOptionsGivesTheSameValues) {
  for (const auto& s : kSplit) {
    SCOPED_TRACE(std::string(s.command) + " " + s.old_args[0]);
    const auto a = weft_app(), b = weft_app();
    const CLI::App* new_sub = parse(*b, s.command, s.new_args);
    EXPECT_EQ(given_values(*parse(*a, s.command, s.old_args)), given_values(*new_sub));
    for (const char* n : s.new_names) EXPECT_EQ(new_sub->get_option(n)->count(), 1u) << n;
  }
}

TEST(OptionSpelling, HelpListsOnlyTheNewNames) {
  const auto app = weft_app();
  for (const auto& r : kRenamed) {
    const std::string help = app->get_subcommand(r.command)->help();
    EXPECT_TRUE(lists(help, r.new_name)) << r.command << " " << r.new_name << "\n" << help;
    EXPECT_FALSE(lists(help, r.old_name)) << r.command << " " << r.old_name << "\n" << help;
  }
  for (const auto& s : kSplit) {
    const std::string help = app->get_subcommand(s.command)->help();
    for (const char* n : s.new_names) EXPECT_TRUE(lists(help, n)) << s.command << " " << n;
    EXPECT_FALSE(lists(help, s.old_args[0])) << s.command << " " << s.old_args[0] << "\n" << help;
  }
}

TEST(OptionSpelling, AnOldNameKeepsItsChecks) {
  const auto app = weft_app();
  EXPECT_THROW(parse(*app, "bake", {"--fit-sgs", "0"}), CLI::ValidationError);  // --sg-count's range
}

// The split spelling's values reach the kiosk: the same picture at the same size. The turntable
// stands still: its angle follows the wall clock, so a turning camera draws a different frame each run.
TEST(OptionSpelling, WeftRunDrawsTheSameFrameForEitherSizeSpelling) {
  const test::SmallBundle b("swatch", "--no-tables");
  ASSERT_TRUE(b.baked());
  const auto shot = [&](const std::string& name, const std::string& size) {
    const std::filesystem::path png = b.dir() / (name + ".png");
    const std::string cmd = std::string(WEFT_BINARY) + " run --bundle " + b.file().string() + " --state-dir " +
                            (b.dir() / name).string() + " --display headless --panel none --turntable 0 --frames 1 " + size +
                            " --screenshot " + png.string() + " >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(png, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string old_png = shot("old", "--size 40 30"), new_png = shot("new", "--width 40 --height 30");
  ASSERT_GT(new_png.size(), 24u);
  EXPECT_EQ(new_png.substr(16, 8), std::string("\0\0\0\x28\0\0\0\x1e", 8));  // IHDR: 40 x 30
  EXPECT_EQ(old_png, new_png);
}

}  // namespace
}  // namespace weft
