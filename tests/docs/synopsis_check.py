#!/usr/bin/env python3
"""The command synopsis in docs/usage.md against `lenslab --help` and each subcommand's --help.

usage: synopsis_check.py LENSLAB DOCS/usage.md

The synopsis is the first ```-fenced block after the heading "## Synopsis". A command's entry is its
line starting "lenslab NAME" and the indented lines after it. For every subcommand the check asks:
- every option its --help lists (long and short names) appears in its entry, and the entry names no
  option that --help does not list;
- an option --help marks REQUIRED is written bare in the entry (not inside [ ]), any other in [ ];
- the positional SCENE is written [SCENE] when optional and SCENE when required.
It prints every difference and exits 1 when there is one, so the synopsis cannot go stale.
"""
import re
import subprocess
import sys

OPTION = re.compile(r"(?<![\w-])(--?[A-Za-z][\w-]*)")


def run_help(lenslab, *args):
    out = subprocess.run([lenslab, *args, "--help"], capture_output=True, text=True, check=True).stdout
    return out


def sections(text):
    """The lines of a --help text under each heading ("Options:", "Subcommands:"): {heading: [lines]}."""
    found, section = {}, None
    for line in text.splitlines():
        if re.match(r"^\S.*:$", line):
            section = line[:-1]
            found.setdefault(section, [])
        elif section is not None:
            found[section].append(line)
    return found


def help_options(text):
    """Options of one --help text: {name: required}, with short and long names."""
    options = {}
    for line in sections(text).get("Options", []):
        m = re.match(r"^  (\S+)", line)
        if not m or not m.group(1).startswith("-"):
            continue
        names = m.group(1).split(",")
        required = " REQUIRED" in line
        for name in names:
            options[re.sub(r"\{.*\}$", "", name.lstrip("!"))] = required
    return options


def help_subcommands(text):
    subs = []
    for line in sections(text).get("Subcommands", []):
        m = re.match(r"^  (\w+)\s", line)
        if m:
            subs.append(m.group(1))
    return subs


def scene_positional(text):
    """'optional', 'required' or None, from the Usage line."""
    usage = next((l for l in text.splitlines() if l.startswith("Usage:")), "")
    if "[scene]" in usage:
        return "optional"
    if re.search(r"\bscene\b", usage):
        return "required"
    return None


def synopsis_entries(doc_path):
    lines = open(doc_path, encoding="utf-8").read().splitlines()
    try:
        start = lines.index("## Synopsis")
    except ValueError:
        sys.exit(f"{doc_path}: no '## Synopsis' heading")
    i = start + 1
    while i < len(lines) and not lines[i].startswith("```"):
        i += 1
    block = []
    i += 1
    while i < len(lines) and not lines[i].startswith("```"):
        block.append(lines[i])
        i += 1
    entries, current = {}, None
    for line in block:
        m = re.match(r"^lenslab (\S+)", line)
        if m:
            current = m.group(1) if not m.group(1).startswith("-") else ""
            entries.setdefault(current, "")
            entries[current] += " " + line[len("lenslab"):]
        elif line.startswith(" ") and current is not None:
            entries[current] += " " + line
    return entries


def bracket_depths(text):
    """For each option occurrence in `text`: (name, inside square brackets?)."""
    found, depth = [], 0
    i = 0
    while i < len(text):
        c = text[i]
        if c == "[":
            depth += 1
        elif c == "]":
            depth -= 1
        else:
            m = OPTION.match(text, i)  # its lookbehind sees text[i - 1]: no match inside a word
            if m:
                found.append((m.group(1), depth > 0))
                i = m.end()
                continue
        i += 1
    return found


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    lenslab, doc = sys.argv[1], sys.argv[2]
    entries = synopsis_entries(doc)
    problems = []
    top = run_help(lenslab)
    commands = help_subcommands(top)
    # The line "lenslab --help | --version" (the entry named "").
    top_options = {n for n, _ in bracket_depths(entries.get("", ""))}
    for name in ("--help", "--version"):
        if name not in top_options:
            problems.append(f"the synopsis has no 'lenslab {name}' line")
    for command in commands:
        if command not in entries:
            problems.append(f"'lenslab {command}' is missing from the synopsis")
            continue
        text = run_help(lenslab, command)
        options = help_options(text)
        written = bracket_depths(entries[command])
        names = {n for n, _ in written}
        for option, required in sorted(options.items()):
            if option in ("-h", "--help"):
                continue
            if option not in names:
                problems.append(f"lenslab {command}: {option} is in --help but not in the synopsis")
                continue
            bracketed = [b for n, b in written if n == option]
            if required and all(bracketed):
                problems.append(f"lenslab {command}: {option} is required, so write it outside [ ]")
            if not required and not all(bracketed):
                problems.append(f"lenslab {command}: {option} is optional, so write it inside [ ]")
        for option in sorted(names - set(options) - {"-h", "--help"}):
            problems.append(f"lenslab {command}: the synopsis lists {option}, which --help does not")
        scene = scene_positional(text)
        entry = entries[command]
        if scene == "optional" and "[SCENE]" not in entry:
            problems.append(f"lenslab {command}: SCENE is optional, so write [SCENE]")
        if scene == "required" and (" SCENE" not in entry or "[SCENE]" in entry):
            problems.append(f"lenslab {command}: SCENE is required, so write SCENE (not [SCENE])")
    for command in entries:
        if command and command not in commands and not command.isupper():
            problems.append(f"the synopsis lists 'lenslab {command}', which is not a subcommand")
    for p in problems:
        print(f"{doc}: {p}")
    if problems:
        print(f"{len(problems)} differences between the synopsis and --help")
        return 1
    print(f"{doc}: the synopsis matches --help for {len(commands)} subcommands")
    return 0


if __name__ == "__main__":
    sys.exit(main())
