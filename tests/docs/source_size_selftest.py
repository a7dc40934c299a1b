#!/usr/bin/env python3
"""Tests of tools/check-source-size.py on synthetic files (ctest `source_size_selftest`, label docs):
it must flag exactly the files and functions over the limits, whatever braces comments, strings,
character literals and raw strings hold, and its baseline must only let violations shrink."""
import importlib.util
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', '..', 'tools', 'check-source-size.py')
spec = importlib.util.spec_from_file_location('check_source_size', SCRIPT)
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)


def function(name, body_lines, signature='void {}()'):
    """A function whose body spans body_lines lines, `{` line and `}` line included."""
    inner = ['  x += 1;'] * (body_lines - 2)
    return '\n'.join([signature.format(name) + ' {'] + inner + ['}']) + '\n'


def violations(text, path='src/a/File.cpp'):
    return [(v.kind, v.name, v.size) for v in check.measure(path, text)]


class Functions(unittest.TestCase):
    def test_81_lines_flagged_80_not(self):
        text = function('longOne', 81) + function('justFits', 80)
        self.assertEqual(violations(text), [('function', 'longOne', 81)])

    def test_line_number_is_the_signature(self):
        text = '// header\n\n' + function('longOne', 90)
        (v,) = check.measure('src/a/File.cpp', text)
        self.assertEqual(v.line, 3)
        self.assertEqual(check.message(v), 'src/a/File.cpp:3: function longOne is 90 lines (limit 80)')

    def test_braces_in_comments_and_strings_do_not_count(self):
        # Unbalanced braces in every kind of literal and comment: a matcher that saw any of them
        # would end the first function early (no violation) or merge the two (one of 120 lines).
        body = ['  const char* a = "}}}";  // }}',
                "  char b = '}';",
                "  char c = '\\'';",
                '  const char* d = "\\"}";',
                '  /* } */ int e = 1\'000\'000;',
                '  const char* f = R"x(})" }}})x";',
                '  const char* g = u8R"(}})";',
                '#define CLOSE }',
                ] + ['  x += 1;'] * 70
        first = 'void tricky() {\n' + '\n'.join(body) + '\n}\n'   # 80 lines in all
        text = first + function('after', 40)
        self.assertEqual(violations(text), [])
        self.assertEqual([f[0] for f in check.find_functions(check.strip_code(text))], ['tricky', 'after'])
        self.assertEqual(violations(first.replace('{\n', '{\n  x += 1;\n', 1)),
                         [('function', 'tricky', 81)])

    def test_raw_string_with_braces_over_lines(self):
        raw = 'const char* kText = R"glsl(\n' + 'void main() {\n' * 3 + ')glsl";\n'
        text = raw + function('afterRaw', 81)
        self.assertEqual(violations(text), [('function', 'afterRaw', 81)])

    def test_lambdas_count_toward_their_function(self):
        inner = ['  auto f = [&](int y) {'] + ['    x += y;'] * 50 + ['  };'] + ['  f(1);'] * 30
        text = 'int outer() {\n' + '\n'.join(inner) + '\n}\n'
        self.assertEqual(violations(text), [('function', 'outer', 84)])

    def test_members_namespaces_and_constructors(self):
        ctor = 'Foo::Foo(int a) : a_{a}, b_(2), c_{3} {\n' + '  x += 1;\n' * 85 + '}\n'
        member = function('bar', 82, 'int Foo::{}() const')
        inline = 'class Foo {\n public:\n' + function('inlineOne', 83, '  void {}()') + '};\n'
        text = 'namespace lenslab {\nnamespace {\n' + ctor + '}\n' + member + inline + '}\n'
        self.assertEqual(sorted(violations(text)), [('function', 'Foo::Foo', 87),
                                                    ('function', 'Foo::bar', 82),
                                                    ('function', 'inlineOne', 83)])

    def test_initialisers_are_not_functions(self):
        table = 'const int kTable[] = {\n' + '  1,\n' * 100 + '};\n'
        enum = 'enum class Kind {\n' + '  A,\n' * 100 + '};\n'
        default_arg = 'void f(int a, Options o = {}) {\n' + '  x += 1;\n' * 85 + '}\n'
        self.assertEqual(violations(table + enum + default_arg), [('function', 'f', 87)])

    def test_template_with_default_and_operator(self):
        text = (function('clamp', 81, 'template <typename T, int N = 3> T {}(T a)')
                + function('operator==', 81, 'bool {}(const A& a, const A& b)'))
        self.assertEqual(violations(text), [('function', 'clamp', 81), ('function', 'operator==', 81)])

    def test_glsl_layout_blocks(self):
        text = ('#version 450\nlayout(std140, binding = 0) uniform Block {\n' + '  vec4 v;\n' * 90 + '};\n'
                + function('shade', 81, 'vec3 {}(vec3 n)'))
        self.assertEqual(violations(text, 'shaders/x/x.frag'), [('function', 'shade', 81)])


class Files(unittest.TestCase):
    def test_401_lines_flagged_400_not(self):
        self.assertEqual(violations('int a;\n' * 401), [('file', '', 401)])
        self.assertEqual(violations('int a;\n' * 400), [])


class Baseline(unittest.TestCase):
    def run_check(self, files, baseline):
        with tempfile.TemporaryDirectory() as root:
            for rel, text in files.items():
                os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
                with open(os.path.join(root, rel), 'w') as f:
                    f.write(text)
            for rel in ('src/external/glad/gl.c', 'src/scene/Table.inc'):   # left out: vendored, generated
                os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
                with open(os.path.join(root, rel), 'w') as f:
                    f.write(function('huge', 500))
            base = os.path.join(root, 'baseline.txt')
            with open(base, 'w') as f:
                f.write(baseline)
            return check.main(['--root', root, '--baseline', base])

    def test_listed_violation_may_shrink_not_grow(self):
        files = {'src/a/A.cpp': function('big', 90)}
        self.assertEqual(self.run_check(files, 'src/a/A.cpp: function big is 90 lines (limit 80)\n'), 0)
        self.assertEqual(self.run_check(files, 'src/a/A.cpp: function big is 95 lines (limit 80)\n'), 0)
        self.assertEqual(self.run_check(files, 'src/a/A.cpp: function big is 85 lines (limit 80)\n'), 1)

    def test_new_violation_fails(self):
        files = {'src/a/A.cpp': function('big', 90) + function('other', 81)}
        self.assertEqual(self.run_check(files, 'src/a/A.cpp: function big is 90 lines (limit 80)\n'), 1)

    def test_stale_entry_fails(self):
        files = {'src/a/A.cpp': function('big', 60)}
        self.assertEqual(self.run_check(files, 'src/a/A.cpp: function big is 90 lines (limit 80)\n'), 1)
        self.assertEqual(self.run_check(files, ''), 0)

    def test_vendored_and_generated_left_out(self):
        self.assertEqual(self.run_check({'shaders/a/a.frag': function('main', 10)}, ''), 0)


if __name__ == '__main__':
    unittest.main(argv=[sys.argv[0]] + sys.argv[1:], verbosity=1)
