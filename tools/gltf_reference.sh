#!/usr/bin/env bash
# Reference pictures for a gallery list whose files come with no screenshot (the real-file lists): each file
# imported by Blender's glTF importer and rendered with Cycles, framed as vkmc frames it
# (tools/gltf_reference/render_reference.py says how). tools/gltf_gallery.sh --references REF_DIR/references then
# puts each beside vkmc's render on the contact sheet.
#
# Usage: tools/gltf_reference.sh MODELS_DIR REF_DIR --list FILE [--only NAME[,NAME...]] [--spp N] [--timeout S]
#                                [--renders DIR]
#   --renders DIR  a gallery's renders/ folder: each reference takes the size of vkmc's render (its NAME.json)
# Writes REF_DIR/references/NAME.png and REF_DIR/logs/NAME.log; a file Blender cannot import has no picture, and
# its log says why. Needs Debian's blender (installed when missing) and python3-numpy.
set -euo pipefail
usage() { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit "${1:-2}"; }
[[ $# -ge 2 ]] || usage
models=$1 out=$2
shift 2
list="" only="" spp=32 timeout=180 renders=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --list) list=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --renders) renders=$2; shift 2 ;;
    -h|--help) usage 0 ;;
    *) echo "gltf_reference: unknown option $1" >&2; usage ;;
  esac
done
[[ -n $list ]] || { echo "gltf_reference: --list FILE is required" >&2; usage; }
for p in blender python3-numpy; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    sudo_cmd=()
    [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends blender python3-numpy >&2
    break
  fi
done
script="$(cd "$(dirname "$0")" && pwd)/gltf_reference/render_reference.py"
mkdir -p "$out/references" "$out/logs"
made=0 failed=0
while IFS= read -r line; do
  [[ -z ${line// /} || $line == \#* ]] && continue
  IFS='|' read -r name path _ <<<"$line"
  name=$(echo "$name" | sed 's/^ *//; s/ *$//') path=$(echo "$path" | sed 's/^ *//; s/ *$//')
  [[ -n $only && ",$only," != *",$name,"* ]] && continue
  size=(--width 192 --height 192)
  if [[ -n $renders && -f $renders/$name.json ]]; then
    read -r w h < <(python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['width'], d['height'])" \
      "$renders/$name.json")
    size=(--width "$w" --height "$h")
  fi
  rm -f "$out/references/$name.png"
  if timeout "$timeout" blender -b --factory-startup --python "$script" -- "$models/$path" \
      "$out/references/$name.png" "${size[@]}" --spp "$spp" </dev/null > "$out/logs/$name.log" 2>&1 &&
      [[ -s $out/references/$name.png ]]; then
    made=$((made + 1)); printf '%-32s made\n' "$name"
  else
    failed=$((failed + 1)); printf '%-32s no picture (%s)\n' "$name" "$(grep -m1 -iE 'error|exception' "$out/logs/$name.log" | cut -c1-100)"
  fi
done < "$list"
echo "$made references made, $failed without one: $out/references"
