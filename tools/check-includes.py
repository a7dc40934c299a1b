#!/usr/bin/env python3
"""Checks that lenslab's includes run downward (ctest `include_layers`, label docs).

The folders of src/ are layers, top to bottom (docs/development.md, "Folders"):

    python/                   the Python module: the top; it renders a frame as the command
                              line does (app/FrameRender.h)
    app/                      the command line; nothing but python/ includes it
    view/  report/            the viewer's library, the sweep report (side by side, under app/ only)
    render/  raycast/         the raster passes, the CPU reference
    gl/                       contexts, GL objects, shader loading
    plan/                     the frame plan, the user's options, which camera a command uses
    io/                       files: images, camera JSON, COLMAP models, JSON lines, progress
    camera/  scene/           the viewing description; the scene (glTF, bounds, materials)
    lens/                     optics: thin lens, apertures, prescriptions, lens effects
    core/                     errors, numbers, text, reading a file whole, data paths, boxes

A file may include its own folder and any folder on a lower layer; folders side by side on one
layer never include each other (camera/ does not know scenes: what it needs of one, a box, is in
core/). io/ sits under plan/: files are read into the models' types, and choosing among them is
planning. view/ and report/ sit side by side under app/: both use the renderers, neither the other.

Beyond the layers:
- GL's headers (glad, GL/, EGL/, KHR/, OSMesa) only in gl/ and render/: the rest is tested without
  a context.
- The window library (GLFW, Dear ImGui's GLFW and OpenGL backends) only in view/, whose window it
  is; GLFW there after `#define GLFW_INCLUDE_NONE`, so that glad's stays the only GL header.
- The command-line library (CLI11) only in app/.

Each violation is printed as `path:line: #include <what>: rule`, and the exit status is 1.
Generated and vendored code (src/external/) is not checked.

Usage: check-includes.py [--root DIR]
"""
import argparse
import os
import re
import sys

LAYERS = [
    ['core'],
    ['lens'],
    ['camera', 'scene'],
    ['io'],
    ['plan'],
    ['gl'],
    ['render', 'raycast'],
    ['view', 'report'],
    ['app'],
    ['python'],
]
RANK = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}
EXTENSIONS = ('.h', '.hpp', '.cpp', '.cc', '.c', '.inc')
SKIPPED = ('external',)

GL_HEADER = re.compile(r'^(?:glad/|GL/|EGL/|KHR/|GLES\d*/|.*[Oo][Ss][Mm]esa)')
WINDOW_HEADER = re.compile(r'^(?:GLFW/|backends/imgui_impl_)')
CLI_HEADER = re.compile(r'^CLI/')
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def layer_name(rank):
    return ' '.join(f + '/' for f in LAYERS[rank])


def folder_of(src, path):
    """The top folder under src/ that holds path, or None when it is outside src/."""
    rel = os.path.relpath(path, src)
    if rel.startswith('..'):
        return None
    return rel.replace(os.sep, '/').split('/')[0]


def resolve(src, including_file, target, quoted):
    """The folder of the project header an include names, or None for a system or library one.
    Quoted includes are looked up beside the including file first, then under src/ (the one
    include path the libraries give); angle includes under src/ only."""
    candidates = []
    if quoted:
        candidates.append(os.path.join(os.path.dirname(including_file), target))
    candidates.append(os.path.join(src, target))
    for candidate in candidates:
        if os.path.isfile(candidate):
            return folder_of(src, os.path.normpath(candidate))
    return None


def check_file(src, path):
    """[(line, include text, rule)] for one file."""
    problems = []
    folder = folder_of(src, path)
    rank = RANK.get(folder)
    glfw_include_none = False
    with open(path, encoding='utf-8', errors='replace') as f:
        lines = f.readlines()
    in_comment = False
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        if in_comment:
            in_comment = '*/' not in stripped
            continue
        if stripped.startswith('/*') and '*/' not in stripped:
            in_comment = True
            continue
        if re.match(r'#\s*define\s+GLFW_INCLUDE_NONE\b', stripped):
            glfw_include_none = True
        m = INCLUDE.match(line)
        if not m:
            continue
        quoted = m.group(1) == '"'
        target = m.group(2)
        shown = f'#include {m.group(1)}{target}{">" if not quoted else chr(34)}'
        if not quoted and GL_HEADER.match(target) and folder not in ('gl', 'render'):
            problems.append((number, shown, 'GL headers only in gl/ and render/'))
            continue
        if WINDOW_HEADER.match(target):
            if folder != 'view':
                problems.append((number, shown, 'the window library (GLFW, ImGui backends) only in view/'))
            elif target.startswith('GLFW/') and not glfw_include_none:
                problems.append((number, shown, 'GLFW only after #define GLFW_INCLUDE_NONE '
                                                '(glad\'s must be the only GL header)'))
            continue
        if CLI_HEADER.match(target) and folder != 'app':
            problems.append((number, shown, 'the command-line library (CLI11) only in app/'))
            continue
        included = resolve(src, path, target, quoted)
        if included is None or rank is None:
            continue
        if included not in RANK:
            problems.append((number, shown, f'{included}/ is not a layer of docs/development.md'))
        elif RANK[included] > rank:
            problems.append((number, shown,
                             f'{folder}/ (layer "{layer_name(rank)}") may not include {included}/ '
                             f'(higher layer "{layer_name(RANK[included])}"); includes run downward'))
        elif RANK[included] == rank and included != folder:
            problems.append((number, shown,
                             f'{folder}/ may not include {included}/: side by side on layer '
                             f'"{layer_name(rank)}", they stay independent'))
    return problems


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument('--root', default=os.path.dirname(here))
    args = parser.parse_args(argv)
    src = os.path.join(args.root, 'src')

    count, failures = 0, 0
    for folder, dirs, files in os.walk(src):
        rel = os.path.relpath(folder, src).replace(os.sep, '/')
        dirs[:] = sorted(d for d in dirs if not (rel == '.' and d in SKIPPED))
        if rel == '.':
            for d in dirs:
                if d not in RANK:
                    print(f'src/{d}/: a folder that is no layer of tools/check-includes.py; '
                          'place it in LAYERS and in docs/development.md')
                    failures += 1
        for name in sorted(files):
            if not name.endswith(EXTENSIONS):
                continue
            path = os.path.join(folder, name)
            count += 1
            for line, include, rule in check_file(src, path):
                print(f'{os.path.relpath(path, args.root)}:{line}: {include}: {rule}')
                failures += 1
    print(f'check-includes: {count} files, {failures} violation(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
