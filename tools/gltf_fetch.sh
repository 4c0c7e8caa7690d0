#!/usr/bin/env bash
# Lays out the glTF gallery's models (tools/gltf_models.txt) in MODELS_DIR from a git copy of the sample
# assets (docs/journal/gltf.md says which repository and commit), and makes the gltfpack variants. Never run it
# inside the repo: the models are not committed.
# Usage: tools/gltf_fetch.sh ASSETS_GIT_DIR MODELS_DIR
#   ASSETS_GIT_DIR  a clone (or bare mirror) holding commit $commit below
#   MODELS_DIR      where the model folders go (e.g. /work/gltf-models)
# The gltfpack variants need gltfpack on PATH (npm install -g gltfpack@1.3.0) or GLTFPACK=/path/to/gltfpack.
set -euo pipefail
commit=02d48689ce60c8799207f180ae324997e974c956
[[ $# -eq 2 ]] || { sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
src=$1 models=$2
list=$(dirname "$(realpath "$0")")/gltf_models.txt
gd=$(git -C "$src" rev-parse --git-dir 2>/dev/null || echo "$src")
[[ $gd = /* ]] || gd=$src/$gd
git --git-dir="$gd" cat-file -e "$commit^{commit}" ||
  { echo "gltf_fetch: $src has no commit $commit" >&2; exit 2; }
mkdir -p "$models"
absent=0
for dir in $(grep -v '^#' "$list" | awk -F' [|] ' '$3 == "SA" { split($2, a, "/"); print a[1] }' | sort -u); do
  while IFS=$'\t' read -r meta path; do
    sha=$(echo "$meta" | awk '{ print $3 }')
    out=$models/${path#Models/}
    mkdir -p "$(dirname "$out")"
    if git --git-dir="$gd" cat-file -e "$sha" 2>/dev/null; then
      git --git-dir="$gd" cat-file blob "$sha" >"$out"
    else
      echo "gltf_fetch: $path is absent from this copy (a large file left out?)" >&2
      absent=$((absent + 1))
    fi
  done < <(git --git-dir="$gd" ls-tree -r "$commit" "Models/$dir/")
done
gltfpack=${GLTFPACK:-$(command -v gltfpack || true)}
while IFS='|' read -r name path source _; do
  [[ $name = \#* || $(echo "$source" | xargs) != gltfpack ]] && continue
  path=$(echo "$path" | xargs)
  input=$models/$(dirname "$(dirname "$path")")/glTF-Binary/$(basename "$path")
  if [[ -z $gltfpack ]]; then
    echo "gltf_fetch: no gltfpack, $path not made (npm install -g gltfpack@1.3.0)" >&2
    continue
  fi
  mkdir -p "$models/$(dirname "$path")"
  "$gltfpack" -i "$input" -o "$models/$path" -cc >/dev/null
done <"$list"
missing=0
while IFS='|' read -r name path _; do
  [[ $name = \#* || -z ${name// /} ]] && continue
  [[ -f $models/$(echo "$path" | xargs) ]] || { echo "gltf_fetch: missing $(echo "$path" | xargs)" >&2; missing=$((missing + 1)); }
done <"$list"
echo "gltf_fetch: $(grep -vc '^#' "$list") models listed, $missing missing, $absent files absent from the copy; in $models"
