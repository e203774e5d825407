#!/usr/bin/python3
"""Rewrite README.md's usage block from the binary's own `raytrace --help`.

    tools/sync_readme_usage.py [--bin build/raytrace] [--readme README.md]

The block sits between the markers BEGIN and END below, as a fenced code block; everything else in the README
is left alone. The test `readme.usage` (tests/readme_usage.cmake) fails whenever the two differ, so run this
after changing a row of the option table (src/app/arguments.cpp) or the command table (src/app/commands.cpp)
and commit the README with the change.
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = "<!-- usage:begin (written by tools/sync_readme_usage.py from raytrace --help) -->\n"
END = "<!-- usage:end -->\n"


def block(help_text):
    return BEGIN + "```text\n" + help_text + "```\n" + END


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "raytrace"))
    parser.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    args = parser.parse_args()

    help_text = subprocess.run([args.bin, "--help"], check=True, stdout=subprocess.PIPE, text=True).stdout
    with open(args.readme, encoding="utf-8") as f:
        readme = f.read()
    start = readme.find(BEGIN)
    stop = readme.find(END, start + 1)
    if start < 0 or stop < 0:
        sys.exit("%s: no usage block (a line %r, later a line %r)" % (args.readme, BEGIN.strip(), END.strip()))
    updated = readme[:start] + block(help_text) + readme[stop + len(END):]
    if updated == readme:
        print("%s: the usage block already matches %s --help" % (args.readme, args.bin))
        return
    with open(args.readme, "w", encoding="utf-8") as f:
        f.write(updated)
    print("%s: usage block rewritten from %s --help" % (args.readme, args.bin))


if __name__ == "__main__":
    main()
