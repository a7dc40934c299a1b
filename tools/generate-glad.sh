#!/usr/bin/env bash
# Regenerates the committed GL 4.5 core loader in src/external/glad.
# glad2 is a Python package (pip install glad2); --reproducible keeps it offline and the output stable.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
out="$top/src/external/glad"
rm -rf "$out"
glad --reproducible --api gl:core=4.5 --extensions GL_ARB_clip_control,GL_KHR_debug --out-path "$out" c
