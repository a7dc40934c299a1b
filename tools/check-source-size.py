#!/usr/bin/env python3
"""Checks the size of lenslab's sources: files and functions (ctest `source_size`, label docs).

No file in src/ or shaders/ is over 400 lines, and no function over 80 lines (C++ and GLSL).
Generated and vendored code is left out: src/external/ and *.inc files.

A function's length is the lines of its body, from the line of its opening brace to the line of
its closing one. Functions are the bodies found at namespace or class scope (free functions,
member functions, constructors, a lambda stored in a namespace-scope variable); what is inside a
body (lambdas, local classes, blocks) counts toward the function holding it. Braces are matched
on the code only: comments, string and character literals, raw strings and preprocessor lines
are skipped first, so a brace inside them never counts.

The baseline (tools/source-size-baseline.txt) lists the violations that were there when the check
came in, each with its size then. A listed violation may shrink or vanish; a new one, or one that
grew, fails (exit 1); so does a baseline entry that no longer violates ("stale: remove it"), so
that the list only ever shrinks. `--write-baseline` rewrites it from what is measured now.

Usage: check-source-size.py [--root DIR] [--baseline FILE] [--write-baseline] [PATH...]
(PATHs, files or folders, relative to the root; default src and shaders)
"""
import argparse
import collections
import os
import re
import sys

FILE_LIMIT = 400
FUNCTION_LIMIT = 80
EXTENSIONS = ('.h', '.hpp', '.cpp', '.cc', '.c', '.glsl', '.vert', '.frag', '.geom', '.comp',
              '.tesc', '.tese')
EXCLUDED_DIRS = ('src/external/',)
EXCLUDED_SUFFIXES = ('.inc',)

Violation = collections.namedtuple('Violation', 'path line kind name size limit')


def violation_key(v):
    """What identifies a violation across edits (its line moves; its file and name do not)."""
    return (v.path, v.kind, v.name)


def message(v, with_line=True):
    where = f'{v.path}:{v.line}:' if with_line else f'{v.path}:'
    what = 'file' if v.kind == 'file' else f'function {v.name}'
    return f'{where} {what} is {v.size} lines (limit {v.limit})'


# ---------------------------------------------------------------------------------------------
# Lexing: the code with comments, literals and preprocessor lines blanked out (newlines kept, so
# that offsets still give line numbers).

RAW_STRING = re.compile(r'(?:u8|u|U|L)?R"([^()\\\s]{0,16})\(')


def strip_code(text):
    """Returns text of the same length and line structure with comments, string and character
    literals (raw strings included) and preprocessor directives replaced by spaces; a literal
    keeps its quotes, so that `extern "C"` still reads as `extern ""`."""
    out = list(text)
    n = len(text)
    i = 0
    line_start = True  # only whitespace so far on this line

    def blank(a, b):
        for k in range(a, b):
            if out[k] != '\n':
                out[k] = ' '

    while i < n:
        c = text[i]
        if c == '\n':
            line_start = True
            i += 1
            continue
        if c in ' \t\r\f\v':
            i += 1
            continue
        if line_start and c == '#':
            # Preprocessor directive, with its backslash continuations (and comments in it).
            j = i
            while j < n:
                if text[j] == '\n' and text[j - 1] != '\\':
                    break
                if text.startswith('/*', j):
                    end = text.find('*/', j + 2)
                    j = n if end < 0 else end + 2
                    continue
                j += 1
            blank(i, j)
            i = j
            continue
        line_start = False
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            # A line comment ending in a backslash continues on the next line.
            while j < n and text[j - 1] == '\\':
                k = text.find('\n', j + 1)
                j = n if k < 0 else k
            blank(i, j)
            i = j
            continue
        if text.startswith('/*', i):
            end = text.find('*/', i + 2)
            j = n if end < 0 else end + 2
            blank(i, j)
            i = j
            continue
        m = RAW_STRING.match(text, i)
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == '_')):
            close = ')' + m.group(1) + '"'
            end = text.find(close, m.end())
            j = n if end < 0 else end + len(close)
            blank(i, j)
            out[i] = out[j - 1] = '"'
            i = j
            continue
        if c == '"' or c == "'":
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                # A digit separator (1'000'000), not a character literal.
                prev = i - 1
                while prev >= 0 and (text[prev].isalnum() or text[prev] in "'."):
                    prev -= 1
                if text[prev + 1].isdigit():
                    i += 1
                    continue
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            blank(i, j)
            out[i] = c
            out[j - 1] = c
            i = j
            continue
        i += 1
    return ''.join(out)


# ---------------------------------------------------------------------------------------------
# Scopes: which opening braces start a function body.

IDENT = r'[A-Za-z_~][A-Za-z_0-9]*'
QUALIFIED_NAME = re.compile(
    r'((?:' + IDENT + r'\s*(?:<[^<>;{}]*>)?\s*::\s*)*(?:operator\s*(?:\(\s*\)|[^\s(]+)|' + IDENT + r'))\s*$')
DECORATION = re.compile(r'\[\[.*?\]\]|\btemplate\s*<|\b(?:alignas|__attribute__|__declspec)\s*\(')
GLSL_LAYOUT = re.compile(r'\blayout\s*\(')
TRAILING = re.compile(r'^(?:\s|\bconst\b|\bvolatile\b|\bnoexcept\b|\boverride\b|\bfinal\b|\bmutable\b'
                      r'|&&?|\bnoexcept\s*\([^)]*\))*(?:->.*)?$', re.S)
LAMBDA_VARIABLE = re.compile(r'(' + IDENT + r')\s*=\s*\[[^\]]*\]\s*(?:\((.*)\))?[^=]*$', re.S)


def remove_decorations(head, glsl=False):
    """Drops attributes, template parameter lists and GLSL's layout(...) qualifiers, whose
    parentheses are not a parameter list (nor their `=` an assignment)."""
    while True:
        m = DECORATION.search(head) or (GLSL_LAYOUT.search(head) if glsl else None)
        if not m:
            return head
        if m.group(0).startswith('[['):
            head = head[:m.start()] + ' ' * len(m.group(0)) + head[m.end():]
            continue
        opening = m.group(0)[-1]
        closing = {'(': ')', '<': '>'}[opening]
        depth, j = 1, m.end()
        while j < len(head) and depth:
            depth += {opening: 1, closing: -1}.get(head[j], 0)
            j += 1
        head = head[:m.start()] + ' ' * (j - m.start()) + head[j:]


def top_level_parens(head):
    """(start, end) of each parenthesised group at depth 0 of the head."""
    groups, depth, start = [], 0, 0
    for k, ch in enumerate(head):
        if ch == '(':
            if depth == 0:
                start = k
            depth += 1
        elif ch == ')':
            depth -= 1
            if depth == 0:
                groups.append((start, k))
    return groups


OPERATOR = re.compile(r'\boperator\s*(?:<<=|>>=|<=>|->\*|<<|>>|<=|>=|->|\(\s*\)|\[\s*\]|[^\s\w(]{1,2})')
TEMPLATE_ARGUMENTS = re.compile(r'<[^<>;{}]*>')


def mask_templates(h):
    """The head with operator symbols turned into identifier characters and template argument
    lists (`function<int()>`, `map<K, vector<V>>`) blanked, keeping every offset, so that their
    brackets and parentheses are not taken for a parameter list."""
    h = OPERATOR.sub(lambda m: 'operator' + re.sub(r'[^\s]', '_', m.group(0)[8:]), h)
    while True:
        masked = TEMPLATE_ARGUMENTS.sub(lambda m: ' ' * len(m.group(0)), h)
        if masked == h:
            return h
        h = masked


def classify(head, glsl=False):
    """What an opening brace at namespace or class scope opens, from the text before it since the
    last `;`, `{` or `}` there: ('namespace', None), ('class', None), ('function', name),
    ('initializer', None) for a member's brace initialiser inside a constructor's initialiser
    list, or ('other', None) (an enum, an aggregate's initialiser)."""
    original = remove_decorations(head, glsl)
    h = mask_templates(original)
    if re.search(r'\bnamespace\b', h) or re.match(r'\s*extern\s*""\s*$', h):
        return ('namespace', None)
    lam = LAMBDA_VARIABLE.search(h)
    if lam:
        return ('function', lam.group(1))
    groups = top_level_parens(h)
    if groups:
        first_open = groups[0][0]
        before = h[:first_open]
        name = QUALIFIED_NAME.search(before)
        no_assignment = '=' not in before
        if name and no_assignment and not re.search(r'\b(?:enum|decltype|sizeof)\s*$', before):
            last_close = groups[-1][1]
            tail = h[last_close + 1:]
            if TRAILING.match(tail) or re.match(r'\s*:(?!:)', h[groups[0][1] + 1:]):
                text = original[name.start(1):name.end(1)]
                return ('function', re.sub(r'\s+', ' ', re.sub(r'\s*::\s*', '::', text)))
    if re.search(r'\b(?:class|struct|union)\b', h) and '=' not in h:
        return ('class', None)
    return ('other', None)


def in_initializer_list(head):
    """Whether the head is a constructor's signature followed by `:` (a member initialiser list)."""
    h = mask_templates(remove_decorations(head))
    groups = top_level_parens(h)
    return bool(groups) and re.match(r'\s*:(?!:)', h[groups[0][1] + 1:]) is not None \
        and classify(h[:groups[0][1] + 1])[0] == 'function'


def find_functions(code, glsl=False):
    """[(name, first line, opening-brace line, closing-brace line)] for each function body at
    namespace or class scope of the stripped code."""
    functions = []
    line_of = []
    line = 1
    for ch in code:
        line_of.append(line)
        if ch == '\n':
            line += 1
    stack = []          # kinds of the open scopes: namespace/class (scopes we look inside) or skip
    head_start = 0      # where the current head began at this scope
    k, n = 0, len(code)
    while k < n:
        ch = code[k]
        if stack and stack[-1][0] == 'skip':
            # Inside a function body or another brace we do not look into: match braces only.
            if ch == '{':
                stack.append(('skip', None, k))
            elif ch == '}':
                kind, info, opened = stack.pop()
                if info is not None:
                    name, start = info
                    functions.append((name, line_of[start], line_of[opened], line_of[k]))
                if not stack or stack[-1][0] != 'skip':
                    head_start = k + 1
            k += 1
            continue
        if ch == ';':
            head_start = k + 1
        elif ch == '}':
            if stack:
                stack.pop()
            head_start = k + 1
        elif ch == '{':
            head = code[head_start:k]
            prev = head.rstrip()[-1:]
            open_parens = head.count('(') - head.count(')')
            if open_parens > 0 or (in_initializer_list(head) and (prev.isalnum() or prev in '_>')):
                # a brace inside parentheses (a default argument `= {}`), or a member's brace
                # initialiser in a constructor's list `: value_{x}`: skip it, the head goes on
                depth, j = 1, k + 1
                while j < n and depth:
                    depth += {'{': 1, '}': -1}.get(code[j], 0)
                    j += 1
                k = j
                continue
            kind, name = classify(head, glsl)
            if kind == 'initializer':
                kind = 'other'
            if kind in ('namespace', 'class'):
                stack.append((kind, None, k))
                head_start = k + 1
            elif kind == 'function':
                start = head_start + len(head) - len(head.lstrip())
                stack.append(('skip', (name, start), k))
            else:
                stack.append(('skip', None, k))
        k += 1
    return functions


def measure(path, text):
    """The violations of one file's text."""
    found = []
    lines = len(text.splitlines())
    if lines > FILE_LIMIT:
        found.append(Violation(path, 1, 'file', '', lines, FILE_LIMIT))
    glsl = not path.endswith(('.h', '.hpp', '.cpp', '.cc', '.c'))
    for name, first, opened, closed in find_functions(strip_code(text), glsl):
        size = closed - opened + 1
        if size > FUNCTION_LIMIT:
            found.append(Violation(path, first, 'function', name, size, FUNCTION_LIMIT))
    return found


def source_files(root, paths):
    for top in paths:
        full = os.path.join(root, top)
        if os.path.isfile(full):
            yield top
            continue
        for folder, dirs, files in os.walk(full):
            dirs.sort()
            for f in sorted(files):
                rel = os.path.relpath(os.path.join(folder, f), root).replace(os.sep, '/')
                if not f.endswith(EXTENSIONS) or f.endswith(EXCLUDED_SUFFIXES):
                    continue
                if any(rel.startswith(d) for d in EXCLUDED_DIRS):
                    continue
                yield rel


BASELINE_LINE = re.compile(r'^(\S+): (?:file|function (\S+)) is (\d+) lines')


def read_baseline(path):
    entries = collections.defaultdict(list)
    if not path or not os.path.exists(path):
        return entries
    with open(path, encoding='utf-8') as f:
        for number, raw in enumerate(f, 1):
            text = raw.strip()
            if not text or text.startswith('#'):
                continue
            m = BASELINE_LINE.match(text)
            if not m:
                raise SystemExit(f'{path}:{number}: cannot read "{text}" '
                                 '(expected "PATH: file is N lines" or "PATH: function NAME is N lines")')
            kind = 'function' if m.group(2) else 'file'
            entries[(m.group(1), kind, m.group(2) or '')].append(int(m.group(3)))
    return entries


def compare(violations, baseline):
    """(failures, notes): each a list of lines. Violations of one key are matched to its
    baseline sizes largest to largest."""
    failures, notes = [], []
    current = collections.defaultdict(list)
    for v in violations:
        current[violation_key(v)].append(v)
    for key in sorted(set(current) | set(baseline)):
        now = sorted(current.get(key, []), key=lambda v: -v.size)
        then = sorted(baseline.get(key, []), reverse=True)
        for i, v in enumerate(now):
            if i >= len(then):
                failures.append(message(v))
            elif v.size > then[i]:
                failures.append(message(v) + f'; it grew from {then[i]} in the baseline')
            elif v.size < then[i]:
                notes.append(message(v) + f'; down from {then[i]}: lower it in the baseline')
        for size in then[len(now):]:
            path, kind, name = key
            what = 'file' if kind == 'file' else f'function {name}'
            failures.append(f'{path}: {what} is {size} lines in the baseline but no longer '
                            'over the limit: stale: remove it')
    return failures, notes


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument('--root', default=os.path.dirname(here))
    parser.add_argument('--baseline', default=None,
                        help='default: tools/source-size-baseline.txt under the root')
    parser.add_argument('--write-baseline', action='store_true')
    parser.add_argument('paths', nargs='*', default=['src', 'shaders'])
    args = parser.parse_args(argv)
    baseline_path = args.baseline or os.path.join(args.root, 'tools', 'source-size-baseline.txt')

    violations = []
    for rel in source_files(args.root, args.paths):
        with open(os.path.join(args.root, rel), encoding='utf-8', errors='replace') as f:
            violations.extend(measure(rel, f.read()))

    if args.write_baseline:
        with open(baseline_path, 'w', encoding='utf-8') as f:
            f.write('# Violations of tools/check-source-size.py when it came in: files over 400 lines,\n'
                    '# functions over 80. This list may only shrink; the check fails on a stale line.\n')
            for v in sorted(violations, key=lambda v: (v.path, v.kind != 'file', v.name)):
                f.write(message(v, with_line=False) + '\n')
        print(f'check-source-size: wrote {len(violations)} entries to {baseline_path}')
        return 0

    baseline = read_baseline(baseline_path)
    failures, notes = compare(violations, baseline)
    for line in notes:
        print('note: ' + line)
    for line in failures:
        print(line)
    print(f'check-source-size: {len(violations)} over the limits (the baseline lists '
          f'{sum(len(s) for s in baseline.values())}); {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
