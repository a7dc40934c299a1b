#!/usr/bin/env python3
"""Tests of tools/check-includes.py on small synthetic trees (ctest `include_layers_selftest`, label
docs): each rule flags exactly the include that breaks it, naming file, line and rule."""
import contextlib
import importlib.util
import io
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', '..', 'tools', 'check-includes.py')
spec = importlib.util.spec_from_file_location('check_includes', SCRIPT)
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)

# One harmless header per layer, so that includes of them resolve.
BASE_TREE = {f'src/{folder}/{folder.capitalize()}.h': '#pragma once\n' for folder in check.RANK}


def run(files):
    """(exit status, printed lines) of the check over BASE_TREE plus `files`."""
    with tempfile.TemporaryDirectory() as root:
        for rel, text in {**BASE_TREE, **files}.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), 'w') as f:
                f.write(text)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = check.main(['--root', root])
        return status, out.getvalue().splitlines()[:-1]  # the last line is the summary


class Layers(unittest.TestCase):
    def test_downward_and_own_layer_pass(self):
        status, lines = run({'src/plan/Plan.cpp': '#include "plan/Plan.h"\n#include "io/Io.h"\n#include "camera/Camera.h"\n'
                                                  '#include "lens/Lens.h"\n#include "core/Core.h"\n#include <vector>\n'})
        self.assertEqual((status, lines), (0, []))

    def test_upward_fails_naming_file_line_and_rule(self):
        status, lines = run({'src/scene/gltf/Reader.cpp': '// reads files\n#include "io/Io.h"\n'})
        self.assertEqual(status, 1)
        self.assertEqual(len(lines), 1)
        self.assertTrue(lines[0].startswith('src/scene/gltf/Reader.cpp:2: #include "io/Io.h": scene/'), lines[0])
        self.assertIn('includes run downward', lines[0])

    def test_side_by_side_fails(self):
        status, lines = run({'src/camera/Depth.h': '#include "scene/Scene.h"\n'})
        self.assertEqual(status, 1)
        self.assertIn('side by side', lines[0])

    def test_relative_include_resolves_to_its_folder(self):
        self.assertEqual(run({'src/io/Reader.cpp': '#include "Io.h"\n'})[0], 0)
        self.assertEqual(run({'src/core/Reader.cpp': '#include "../app/App.h"\n'})[0], 1)


class Libraries(unittest.TestCase):
    def test_gl_headers_only_in_gl_and_render(self):
        self.assertEqual(run({'src/render/Pass.cpp': '#include <glad/gl.h>\n', 'src/gl/Ctx.cpp': '#include <EGL/egl.h>\n'})[0], 0)
        status, lines = run({'src/camera/Matrix.h': '#include <glad/gl.h>\n', 'src/view/View.cpp': '#include <GL/osmesa.h>\n'})
        self.assertEqual(status, 1)
        self.assertEqual(len(lines), 2)
        self.assertTrue(all('GL headers only in gl/ and render/' in line for line in lines))

    def test_project_gl_folder_is_not_a_gl_header(self):
        self.assertEqual(run({'src/view/View.cpp': '#include "gl/Gl.h"\n'})[0], 0)

    def test_glfw_only_in_view_and_after_include_none(self):
        ok = '#define GLFW_INCLUDE_NONE\n#include <GLFW/glfw3.h>\n#include <backends/imgui_impl_glfw.h>\n'
        self.assertEqual(run({'src/view/Window.h': ok})[0], 0)
        self.assertEqual(run({'src/view/Window.h': '#include <GLFW/glfw3.h>\n'})[0], 1)
        self.assertEqual(run({'src/app/Main.cpp': ok})[0], 1)

    def test_cli11_only_in_app(self):
        self.assertEqual(run({'src/app/Main.cpp': '#include <CLI/CLI.hpp>\n'})[0], 0)
        self.assertEqual(run({'src/plan/Options.cpp': '#include <CLI/CLI.hpp>\n'})[0], 1)

    def test_unknown_folder_fails(self):
        status, lines = run({'src/misc/Thing.h': '#pragma once\n'})
        self.assertEqual(status, 1)
        self.assertIn('src/misc/', lines[0])


if __name__ == '__main__':
    unittest.main(argv=[sys.argv[0]] + sys.argv[1:], verbosity=1)
