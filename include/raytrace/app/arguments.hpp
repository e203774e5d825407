// The command line's words turned into values, by one table of options: each option's spelling, argument,
// help text and effect are given once, and the parsing, the help, the man page and the shell completion all
// come from that table.
#pragma once

#include <string>
#include <vector>

#include "raytrace/parse/scene_file.hpp"
#include "raytrace/render/options.hpp"

namespace rt {

constexpr int kMaxThreads = 1024;  // for --threads

// `s` as a whole number in [lo, hi], or an Error naming `what`.
int parseInt(const std::string& s, const char* what, int lo, int hi);

// A comma-separated list of whole numbers, each in [lo, hi] ("64,16"), or an Error naming `what`.
std::vector<int> parseCounts(const std::string& s, const char* what, int lo, int hi);

// The words after a command: its positional arguments and what its options say.
struct Words {
  std::vector<std::string> positional;
  RenderOptions options;
  bool stats = false, statsJson = false, quiet = false;  // not render options: they say how a run is watched
  bool display = false;                                  // --display: the picture in a window as it renders
  std::string preview;                                   // --preview: the picture so far, in this file
  bool writeAnywhere = false;                            // nor these: they are about the files render makes
  std::string output;                                    // -o's value; "" without -o
  std::string tile, region;                              // --tile's and --region's values; "" without them
  bool resume = false;  // --resume: a tile already written for this very render is kept
  std::string manifest;  // --manifest's value: where to list the files read and the images written
  LoadOptions load;     // --dialect, -L, -D: how the scene file is read
  // The options given that only some commands take, as spelled (before any '='), in command-line order.
  std::vector<std::string> scoped;
};

// Which commands take an option; the others refuse it.
enum class Scope {
  Any,     // every command that reads a scene
  Render,  // render only
  Image,   // the commands that write images (raycast, render)
};

// Where --help lists an option: under "options:" or "image options (raycast, render):".
enum class Section { General, Image };

// How an option takes its value.
enum class Form {
  Switch,    // -fresnel
  Joined,    // --depth=N
  Either,    // --threads N or --threads=N
  Optional,  // --stats or --stats=json
};

struct Option {
  const char* name;      // "--depth"
  const char* alias;     // another spelling ("--output" for -o), or nullptr
  const char* argument;  // what the value looks like in the help ("N", "auto|always|never"); nullptr for a Switch
  Form form;
  Scope scope;
  Section section;
  const char* help;      // lines of at most 68 characters, joined by '\n'
  // Sets the value in `words`: `value` is "" for a Switch, `word` the option as written ("--output=").
  void (*apply)(Words& words, const std::string& value, const std::string& word);
  const char* missing = "needs a value";  // the message when an Either option is last, with no value
};

// Every option of the commands that read a scene, in the order --help lists them.
const std::vector<Option>& optionTable();

// What the option words `args[first…]` say, and the other words as positional arguments. A word is an option
// when it starts with '-' and a letter or a second '-' (so "-5" is a number). Throws an Error for an unknown
// option (naming the nearest if it looks like a typo) or a bad value.
Words readWords(const std::vector<std::string>& args, size_t first = 0);

// `options` with one option word (`-fresnel`, `--depth=3`, ...) applied, or an Error for an unknown or bad one.
RenderOptions parseFlag(const std::string& flag, RenderOptions options);

// The help of the options of `section`, under its heading, as --help lists them.
std::string optionsHelp(Section section);

// The option's spelling with its argument as the help shows it: "--depth=N", "-o, --output FILE".
std::string optionLabel(const Option& option);

// The name among `names` nearest to `word` by edit distance, if a typo's distance away (at most 2); nullptr
// otherwise.
const char* nearestName(const std::string& word, const std::vector<const char*>& names);

// The flags that give `options` the values that change pixels, in a fixed order, defaults left out: ""
// or "--depth=3 -ss=2 -fresnel". Two renders with the same flags here make the same pixels of the same scene.
std::string pixelFlags(const RenderOptions& options);

}  // namespace rt
