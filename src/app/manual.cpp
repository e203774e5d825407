#include "raytrace/app/manual.hpp"

#include <vector>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/app/povray_command_line.hpp"

namespace rt {

namespace {

// `text` as roff prints it literally: backslashes and hyphens escaped, a leading '.' or '\'' defused.
std::string roff(const std::string& text) {
  std::string out = text.empty() || (text[0] != '.' && text[0] != '\'') ? "" : "\\&";
  for (const char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  return out;
}

// An option's help on one line: the table wraps it for the terminal, man wraps it again.
std::string oneLine(const char* help) {
  std::string line(help);
  for (char& c : line) {
    if (c == '\n') c = ' ';
  }
  return line;
}

bool takes(const CommandSummary& c, const Option& o) {
  return c.readsScene && (o.scope == Scope::Any || (o.scope == Scope::Image && c.writesImage) ||
                          (o.scope == Scope::Render && c.isRender));
}

// The values an option's argument lists ("auto|always|never"), space-separated; "" if it names no choices.
std::string choices(const Option& o) {
  const std::string argument = o.argument ? o.argument : "";
  if (argument.find('|') == std::string::npos) return "";
  std::string words = argument;
  for (char& c : words) {
    if (c == '|') c = ' ';
  }
  return words;
}

}  // namespace

std::string manPage() {
  std::string page = ".TH RAYTRACE 1 \"\" \"raytrace " RAYTRACE_VERSION "\" \"User Commands\"\n"
                     ".SH NAME\nraytrace \\- ray tracer for POV\\-Ray\\-style and CS 3451 .cli scene files\n"
                     ".SH SYNOPSIS\n";
  for (const CommandSummary& c : commandSummaries()) page += ".nf\n" + roff(c.usage) + "\n.fi\n";
  page += ".nf\nraytrace \\-\\-help\nraytrace \\-\\-version\n" + roff(kPovRayUsage) + "\n.fi\n"
          ".SH DESCRIPTION\n"
          "raytrace renders a scene file to an image, or prints what one ray of it does in the text formats of the "
          "Cal Poly CSC 473 ray\\-tracing course. A scene is a POV\\-Ray\\-style file (.pov) or a CS 3451 .cli file; "
          "its language comes from the extension, or else from its first meaningful line. "
          "Pixel y grows upward (row 0 is the bottom). When the first argument is a POV\\-Ray switch (+I, +W, "
          "\\-D ...), an .ini file or Input_File_Name=..., the command line is read as POV\\-Ray 3.7 reads it, "
          "animation frames (+KFI, +KFF) included: see docs/povray\\-command\\-line.md.\n"
          ".SH COMMANDS\n";
  for (const CommandSummary& c : commandSummaries()) page += ".TP\n.B " + c.name + "\n" + roff(c.summary) + "\n";
  const auto section = [&](Section s, const char* heading) {
    page += std::string(".SH ") + heading + "\n";
    for (const Option& o : optionTable()) {
      if (o.section == s) page += ".TP\n.B " + roff(optionLabel(o)) + "\n" + roff(oneLine(o.help)) + "\n";
    }
  };
  section(Section::General, "OPTIONS");
  section(Section::Image, "\"IMAGE OPTIONS\"");
  page += ".SH \"EXIT STATUS\"\n0 when every image and text was written; 1 after an error, reported on one "
          "line of the standard error (\\fIfile\\fR:\\fIline\\fR:\\fIcolumn\\fR: error: ...), with no file "
          "written or replaced.\n"
          ".SH EXAMPLES\n.nf\nraytrace render scene.pov 640 480 \\-ss=3 \\-o scene.png\n"
          "raytrace render scene.pov 640 480 \\-\\-display \\-\\-stats=json\n"
          "raytrace pixelcolor scene.pov 640 480 320 240\n"
          "raytrace +Iscene.pov +W640 +H480 +KFI0 +KFF9 +Oframe\n.fi\n"
          ".SH \"SEE ALSO\"\nThe documentation installed with raytrace (README.md and docs/), usually in "
          "/usr/share/doc/raytrace.\n";
  return page;
}

std::string bashCompletion() {
  std::string commands;
  for (const CommandSummary& c : commandSummaries()) commands += (commands.empty() ? "" : " ") + c.name;
  std::string script =
      "# bash completion for raytrace, written by raytrace_manual from its command and option tables.\n"
      "_raytrace() {\n"
      "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} options= values=\n"
      "  local commands=\"" + commands + "\"\n"
      "  if ((COMP_CWORD == 1)); then\n"
      "    COMPREPLY=($(compgen -W \"$commands --help --version\" -- \"$cur\"))\n"
      "    return\n"
      "  fi\n"
      "  case ${COMP_WORDS[1]} in\n";
  for (const CommandSummary& c : commandSummaries()) {
    std::string options;
    for (const Option& o : optionTable()) {
      if (!takes(c, o)) continue;
      for (const char* name : {o.name, o.alias}) {
        if (!name) continue;
        const std::string n(name);
        options += (options.empty() ? "" : " ") +
                   (o.form == Form::Joined ? n + "=" : o.form == Form::Optional ? n + " " + n + "=" : n);
      }
    }
    if (c.name == "merge") options = "-o --output --threads";
    if (c.name == "convert") options = "--name";
    if (c.name == "help") options = "";
    script += "    " + c.name + ") options=\"" + options + " --help\" ;;\n";
  }
  script += "  esac\n"
            "  # An option and its value: --name=VALUE comes as three words (--name, =, VALUE).\n"
            "  local option=$prev\n"
            "  [[ $prev == = ]] && option=${COMP_WORDS[COMP_CWORD-2]}\n"
            "  [[ $cur == = ]] && option=$prev cur=\n"
            "  case $option in\n";
  for (const Option& o : optionTable()) {
    if (!choices(o).empty()) script += "    " + std::string(o.name) + ") values=\"" + choices(o) + "\" ;;\n";
  }
  script += "  esac\n"
            "  if [[ -n $values && ( $prev == = || ${COMP_WORDS[COMP_CWORD]} == = ) ]]; then\n"
            "    COMPREPLY=($(compgen -W \"$values\" -- \"$cur\"))\n"
            "  elif [[ ${COMP_WORDS[1]} == help ]]; then\n"
            "    ((COMP_CWORD == 2)) && COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\"))\n"
            "  elif [[ $cur == -* ]]; then\n"
            "    COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
            "    [[ ${COMPREPLY[0]-} == *= ]] && compopt -o nospace 2>/dev/null\n"
            "  else\n"
            "    compopt -o filenames 2>/dev/null\n"
            "    case $prev in\n"
            "      -o|--output|--preview) COMPREPLY=($(compgen -f -- \"$cur\")) ;;\n"
            "      *) if [[ ${COMP_WORDS[1]} == merge ]]; then\n"
            "           COMPREPLY=($(compgen -d -- \"$cur\") $(compgen -f -X '!*.exr' -- \"$cur\"))\n"
            "         elif [[ ${COMP_WORDS[1]} == convert ]]; then\n"
            "           COMPREPLY=($(compgen -d -- \"$cur\") $(compgen -f -X '!*.obj' -- \"$cur\")"
            " $(compgen -f -X '!*.ply' -- \"$cur\") $(compgen -f -X '!*.inc' -- \"$cur\"))\n"
            "         else\n"
            "           COMPREPLY=($(compgen -d -- \"$cur\") $(compgen -f -X '!*.pov' -- \"$cur\")"
            " $(compgen -f -X '!*.cli' -- \"$cur\"))\n"
            "         fi ;;\n"
            "    esac\n"
            "  fi\n"
            "}\n"
            "complete -F _raytrace raytrace\n";
  return script;
}

std::string zshCompletion() {
  // _arguments and _describe read '[', ']' and ':' in descriptions; single quotes close the spec.
  const auto escape = [](const std::string& text) {
    std::string out;
    for (const char c : text) {
      if (c == '[' || c == ']' || c == ':') out += '\\';
      if (c == '\'') out += "'\\'";
      out += c;
    }
    return out;
  };
  std::string script =
      "#compdef raytrace\n"
      "# zsh completion for raytrace, written by raytrace_manual from its command and option tables.\n"
      "local -a raytrace_commands  # not `commands`: zsh has a parameter of that name\n"
      "raytrace_commands=(\n";
  for (const CommandSummary& c : commandSummaries()) script += "  '" + c.name + ":" + escape(c.summary) + "'\n";
  script += ")\n"
            "if (( CURRENT == 2 )); then\n"
            "  _describe -t commands 'raytrace command' raytrace_commands\n"
            "  return\n"
            "fi\n"
            "local scene='*:scene file:_files -g \"*.(pov|cli)\"'\n"
            "case $words[2] in\n"
            "  help) (( CURRENT == 3 )) && _describe -t commands 'command' raytrace_commands ;;\n"
            "  merge) _arguments '(-o --output)'{-o,--output}'[the image to write]:image:_files' "
            "'--threads[threads]:N:' '*:tile:_files -g \"*.exr\"' ;;\n"
            "  convert) _arguments '--name[the identifier the include declares]:NAME:' "
            "'1:mesh file:_files -g \"*.(obj|ply)\"' '2:include:_files -g \"*.inc\"' ;;\n";
  for (const CommandSummary& c : commandSummaries()) {
    if (!c.readsScene) continue;
    script += "  " + c.name + ") _arguments";
    for (const Option& o : optionTable()) {
      if (!takes(c, o)) continue;
      for (const char* name : {o.name, o.alias}) {
        if (!name) continue;
        const std::string n(name), description = "[" + escape(oneLine(o.help)) + "]";
        const std::string values = choices(o).empty() ? "" : "(" + choices(o) + ")";
        const std::string argument = o.argument ? escape(o.argument) : "";
        switch (o.form) {
          case Form::Switch: script += " '" + n + description + "'"; break;
          case Form::Joined: script += " '" + n + "=-" + description + ":" + argument + ":" + values + "'"; break;
          case Form::Either:
            script += " '" + n + description + ":" + argument + ":" + (argument == "FILE" ? "_files" : " ") + "'";
            break;
          case Form::Optional: script += " '" + n + "=-" + description + "::" + argument + ":" + values + "'"; break;
        }
      }
    }
    script += " \"$scene\" ;;\n";
  }
  return script + "esac\n";
}

}  // namespace rt
