#!/usr/bin/env bash
# Fetches the external glTF test corpus (the ctest entry `corpus`) for a machine that has network
# access: 29 Khronos sample models and 53 glTF-Validator test files, at pinned commits, laid out as
# tests/scene/gltf_loader_test.cpp expects (samples/<Model>/<variant>/..., invalid/base/...,
# invalid/ext/..., invalid/expected.json). Prints the cmake option that points a build at it.
#
#   tools/fetch-gltf-corpus.sh [FOLDER]      FOLDER defaults to build/gltf-corpus in this repository
#
# Needs git and python3. Each source is fetched as one commit (depth 1) without blobs, with a
# sparse checkout of just the files listed in tools/gltf-corpus.tsv, so only those are downloaded
# (about 31 MB), not the repositories (about 1 GB for the sample models).
#
# UNTESTED against GitHub: it was written on a machine without network access. What could be run
# there was run: bash -n, and the whole script against local mirrors of the two repositories
# (file:// URLs, holding the corpus's files at the listed paths).
#
# The pins are the commits that ../shared/gltf/README.md records for the corpus the tests were
# written against (its samples/MANIFEST.json repeats the first):
#   samples    DRx3D/glTF-Sample-Assets-OLD 02d48689ce60c8799207f180ae324997e974c956 (2023-05-23),
#              the staging copy from which KhronosGroup/glTF-Sample-Assets was made; its Models/
#              tree is the glTF 2.0 models of KhronosGroup/glTF-Sample-Models. It is the source
#              the corpus was copied from, so the files here are byte for byte those the tests saw.
#   validator  KhronosGroup/glTF-Validator 434283be08a668a8fb4e437145630ddbf93b0686 (2025-12-30)
# Every fetched file is compared with the git blob SHA-1 that the list records (the same hash
# git uses, so a file that matches is the one the tests were written against); a difference is
# reported, not fatal. invalid/expected.json and samples/MANIFEST.json are written from what was
# fetched. Not reproduced: ../shared/gltf's README.md, its licenses/ folder and the six
# LICENSE.upstream.md files (licence texts taken from KhronosGroup/glTF-Sample-Assets at a commit
# that was not recorded); each model's own LICENSE.md and invalid/LICENSE.txt are fetched.
set -euo pipefail

samples_repo=DRx3D/glTF-Sample-Assets-OLD
samples_url=${LENSLAB_CORPUS_SAMPLES_URL:-https://github.com/$samples_repo.git}
samples_commit=02d48689ce60c8799207f180ae324997e974c956
validator_repo=KhronosGroup/glTF-Validator
validator_url=${LENSLAB_CORPUS_VALIDATOR_URL:-https://github.com/$validator_repo.git}
validator_commit=434283be08a668a8fb4e437145630ddbf93b0686
# The URLs may name a mirror. Overriding the commits is for testing this script against a mirror
# whose commits differ; the corpus it then makes is not the pinned one.
samples_commit=${LENSLAB_CORPUS_SAMPLES_COMMIT:-$samples_commit}
validator_commit=${LENSLAB_CORPUS_VALIDATOR_COMMIT:-$validator_commit}

top=$(cd "$(dirname "$0")/.." && pwd)
list="$top/tools/gltf-corpus.tsv"

die() {
  echo "fetch-gltf-corpus: $*" >&2
  exit 1
}

case ${1:-} in
  -h | --help)
    sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  -*) die "unknown option $1 (usage: $0 [FOLDER])" ;;
esac
[ $# -le 1 ] || die "one folder at most (usage: $0 [FOLDER])"
for tool in git python3; do
  command -v "$tool" >/dev/null || die "$tool is needed and not found"
done
[ -f "$list" ] || die "$list is missing"

dest=${1:-$top/build/gltf-corpus}
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
for sub in samples invalid; do
  [ ! -e "$dest/$sub" ] || die "$dest/$sub exists already; remove it first (or name another folder)"
done

work=$(mktemp -d "${TMPDIR:-/tmp}/lenslab-gltf-corpus.XXXXXX")
trap 'rm -rf "$work"' EXIT

# The sparse-checkout patterns of one source: each listed file anchored at the top ("/path"),
# with the characters that gitignore patterns treat specially escaped (paths hold spaces and
# non-ASCII, which need nothing).
patterns() {
  awk -F '\t' -v source="$1" '
    /^#/ || NF < 5 { next }
    $1 == source { p = $3; gsub(/[\\*?[]/, "\\\\&", p); print "/" p }
  ' "$list"
}

# One commit of a repository, with only the files the patterns name (blobs are fetched on
# checkout, for those files only).
fetch_pinned() {
  local url=$2 commit=$3 repo="$work/$1"
  echo "fetching $url at $commit"
  git init -q "$repo"
  git -C "$repo" remote add origin "$url"
  # Written directly rather than through `git sparse-checkout set`, whose options changed across
  # git versions; non-cone patterns match single files.
  git -C "$repo" config core.sparseCheckout true
  git -C "$repo" config core.sparseCheckoutCone false
  cat >"$repo/.git/info/sparse-checkout"
  git -C "$repo" fetch -q --depth 1 --filter=blob:none origin "$commit" ||
    die "cannot fetch $commit from $url"
  git -C "$repo" -c advice.detachedHead=false checkout -q FETCH_HEAD
  [ "$(git -C "$repo" rev-parse HEAD)" = "$commit" ] || die "$url: got $(git -C "$repo" rev-parse HEAD), not $commit"
}

patterns samples | fetch_pinned samples "$samples_url" "$samples_commit"
# The validator's assets.json files give each test its description (for expected.json).
{ patterns validator; printf '%s\n' /test/base/assets.json '/test/ext/*/assets.json'; } |
  fetch_pinned validator "$validator_url" "$validator_commit"

# Copy each listed file to its place in the corpus and compare it with the recorded blob hash.
copied=0 missing=0 differ=0
while IFS=$'\t' read -r source kind from to sha; do
  case $source in '' | '#'*) continue ;; esac
  src="$work/$source/$from"
  if [ ! -f "$src" ]; then
    echo "missing in $source: $from ($kind)" >&2
    missing=$((missing + 1))
    continue
  fi
  mkdir -p "$(dirname "$dest/$to")"
  cp "$src" "$dest/$to"
  copied=$((copied + 1))
  if [ "$sha" != - ] && [ "$(git hash-object "$dest/$to")" != "$sha" ]; then
    echo "differs from the file the tests were written against: $to" >&2
    differ=$((differ + 1))
  fi
done <"$list"
[ "$missing" -eq 0 ] || die "$missing listed files were not found at the pinned commits (see above); $dest is incomplete"

# invalid/expected.json (one entry per test file, from the validator's recorded reports) and
# samples/MANIFEST.json, in the form the tests and ../shared/gltf use.
python3 - "$list" "$work" "$dest" "$samples_repo" "$samples_commit" <<'PY'
import hashlib, json, os, sys

listing, work, dest, samples_repo, samples_commit = sys.argv[1:]
rows = [line.rstrip("\n").split("\t") for line in open(listing, encoding="utf-8")
        if line.strip() and not line.startswith("#")]

def description(source):
    # test/base/data/<category>/<file> -> test/base/assets.json; test/ext/<EXT>/data/... likewise
    head, _, rest = source.partition("/data/")
    category, _, name = rest.partition("/")
    try:
        with open(os.path.join(work, "validator", head, "assets.json"), encoding="utf-8") as f:
            return json.load(f)[category]["tests"][name]
    except (OSError, KeyError, ValueError):
        return ""

expected = []
for source, kind, origin, to, _ in rows:
    if source != "validator" or kind != "test":
        continue
    with open(os.path.join(dest, to + ".report.json"), encoding="utf-8") as f:
        report = json.load(f)
    issues = report["issues"]
    directory = os.path.dirname(os.path.join(dest, to))
    # The files beside a test that it reads (those a test expects to be missing are not there).
    resources = [r["uri"] for r in report.get("info", {}).get("resources", [])
                 if r.get("storage") == "external" and os.path.isfile(os.path.join(directory, r["uri"]))]
    codes = lambda severity: sorted({m["code"] for m in issues["messages"] if m["severity"] == severity})
    expected.append({
        "file": to[len("invalid/"):], "source": origin, "description": description(origin),
        "resources": resources, "numErrors": issues["numErrors"], "numWarnings": issues["numWarnings"],
        "numInfos": issues["numInfos"], "numHints": issues["numHints"], "errorCodes": codes(0),
        "warningCodes": codes(1), "validatorVersion": report.get("validatorVersion", ""),
    })
with open(os.path.join(dest, "invalid", "expected.json"), "w", encoding="utf-8") as f:
    f.write(json.dumps(expected, indent=1, ensure_ascii=False))

files = []
for source, kind, origin, to, _ in rows:
    if source != "samples":
        continue
    data = open(os.path.join(dest, to), "rb").read()
    files.append({"path": to[len("samples/"):], "source_path": origin,
                  "git_blob_sha1": hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest(), "size": len(data)})
with open(os.path.join(dest, "samples", "MANIFEST.json"), "w", encoding="utf-8") as f:
    f.write(json.dumps({"source_repository": samples_repo, "source_commit": samples_commit, "files": files}, indent=1))
PY

cat >"$dest/README.md" <<EOF
# glTF test corpus for lenslab

Fetched by tools/fetch-gltf-corpus.sh (list: tools/gltf-corpus.tsv):
- samples/: $samples_repo at $samples_commit (folder Models/; "Box With Spaces" and
  "Unicode❤♻Test" renamed BoxWithSpaces and UnicodeTest)
- invalid/: $validator_repo at $validator_commit (test/base/data/ and test/ext/<EXT>/data/)
Licences: each model's LICENSE.md; invalid/LICENSE.txt (Apache-2.0).
EOF

echo "glTF corpus: $copied files in $dest"
[ "$differ" -eq 0 ] || echo "warning: $differ files differ from those the tests were written against (listed above)" >&2
echo "Point a build at it with:"
echo "  cmake -S \"$top\" -B \"$top/build\" -DLENSLAB_GLTF_CORPUS_DIR=\"$dest\""
