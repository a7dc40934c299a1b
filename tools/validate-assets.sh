#!/usr/bin/env bash
# Validates every assets/*/*.gltf with the Khronos glTF validator (npm package gltf-validator,
# installed once into ~/.cache/lenslab-validator). Exits non-zero on any error or warning.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${LENSLAB_VALIDATOR_DIR:-"$HOME/.cache/lenslab-validator"}
if [ ! -d "$cache/node_modules/gltf-validator" ]; then
  mkdir -p "$cache"
  (cd "$cache" && npm install --silent gltf-validator >/dev/null)
fi
NODE_PATH="$cache/node_modules" node - "$top"/assets/*/*.gltf <<'JS'
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');
let bad = 0;
(async () => {
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: file,
      externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
    });
    const i = report.issues;
    console.log(`${path.relative(process.cwd(), file)}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages) if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (i.numErrors > 0 || i.numWarnings > 0) bad++;
  }
  process.exit(bad ? 1 : 0);
})();
JS
