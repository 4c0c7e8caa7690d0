#!/usr/bin/env bash
# The glTF gallery (issue #15): render every model of tools/gltf_models.txt with one vkmc binary, one at a
# time, and write per model the exit code, the first error/warning lines and the seconds, a markdown table
# and a contact sheet (each render beside the model's reference screenshot). The models are fetched
# separately and never committed: docs/journal/gltf.md says how.
#
# Usage: tools/gltf_gallery.sh VKMC MODELS_DIR OUT_DIR [--width W] [--spp N] [--timeout S] [--list FILE]
#                              [--only NAME[,NAME...]] [--no-sheet] [--references DIR] [-- EXTRA vkmc render ARGS]
#   VKMC        the vkmc binary to test (copy it first if someone may rebuild it meanwhile)
#   MODELS_DIR  the fetched collection (e.g. /work/gltf-models)
#   OUT_DIR     outputs, outside the repo (e.g. /work/gltf-out/baseline): renders/NAME.{png,exr,json},
#               logs/NAME.log, results.tsv, gallery.md, contact_sheet.png, contact_sheet_small.png
#   --references DIR  reference pictures DIR/NAME.png, preferred to a model's screenshot (the real-file lists
#               have none: tools/gltf_reference.sh makes them with Blender's importer)
# Defaults: 192 px wide, 16 spp, 300 s per model, the scene's first camera or vkmc's automatic one.
# Needs: bash, python3 (standard library), ImageMagick's convert and montage for the contact sheet
# (apt-get install imagemagick fonts-dejavu-core; --no-sheet skips it).
set -euo pipefail

usage() { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit "${1:-2}"; }
[[ $# -ge 3 ]] || usage
vkmc=$(realpath "$1") models=$(realpath "$2") out=$3
shift 3
width=192 spp=16 timeout_s=300 only="" sheet=1 extra=() references=""
list=$(dirname "$(realpath "$0")")/gltf_models.txt
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --list) list=$(realpath "$2"); shift 2 ;;
    --only) only=",$2,"; shift 2 ;;
    --no-sheet) sheet=0; shift ;;
    --references) references=$(realpath "$2"); shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) usage 0 ;;
    *) echo "gltf_gallery: unknown option $1" >&2; usage ;;
  esac
done
[[ -x $vkmc ]] || { echo "gltf_gallery: $vkmc is not an executable" >&2; exit 2; }
[[ -d $models ]] || { echo "gltf_gallery: no models directory $models (docs/journal/gltf.md says how to fetch it)" >&2; exit 2; }
if [[ $sheet = 1 ]] && ! { convert -version 2>/dev/null | grep -q ImageMagick && command -v montage >/dev/null; }; then
  echo "gltf_gallery: the contact sheet needs ImageMagick (apt-get install imagemagick fonts-dejavu-core)," \
    "or pass --no-sheet" >&2
  exit 2
fi
mkdir -p "$out/renders" "$out/logs" "$out/tiles"
out=$(realpath "$out")
font=()
convert -list font 2>/dev/null | grep -q 'Font: DejaVu-Sans$' && font=(-font DejaVu-Sans)

tsv=$out/results.tsv
printf 'name\tpath\tfeatures\trc\tstatus\twall_s\trender_s\ttriangles\tmessages\n' >"$tsv"

# One line of the table's "messages": the error and warning lines, joined by " / ".
messages() {
  grep -E '(^|: )(error|warning)|^warning|^vkmc: ' "$1" |
    sed -E "s/^vkmc: error: cannot load '[^']*': /error: /; s/^warning +/warning: /; s/[[:space:]]+/ /g" |
    head -n 6 | cut -c1-300 | paste -sd'|' - | sed 's/|/ \/ /g'
}

n=0
while IFS= read -r line; do
  [[ -z ${line// /} || $line = \#* ]] && continue
  IFS='|' read -r name path _ _ features <<<"$line"
  name=$(echo "$name" | xargs) path=$(echo "$path" | xargs) features=$(echo "$features" | sed 's/^ *//; s/ *$//')
  [[ -z $only || $only = *",$name,"* ]] || continue
  n=$((n + 1))
  log=$out/logs/$name.log
  png=$out/renders/$name.png
  rm -f "$png" "$out/renders/$name.exr" "$out/renders/$name.json"
  if [[ ! -f $models/$path ]]; then
    echo "missing file $models/$path (not fetched?)" >"$log"
    rc=127 wall=0
  else
    t0=$(date +%s.%N)
    set +e
    (cd "$models" && timeout "$timeout_s" "$vkmc" render "$path" --width "$width" --spp "$spp" --png "$png" \
      -o "$out/renders/$name.exr" --report "$out/renders/$name.json" "${extra[@]}") >"$log" 2>&1
    rc=$?
    set -e
    wall=$(python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$t0" "$(date +%s.%N)")
  fi
  render_s=$(sed -nE 's/^time +([0-9.]+) s render.*/\1/p' "$log" | head -n1)
  tris=$(sed -nE 's/^scene .*\(([0-9]+) triangles.*/\1/p' "$log" | head -n1)
  if [[ $rc = 0 && -s $png ]]; then status=rendered
  elif [[ $rc = 124 ]]; then status="timed out (${timeout_s} s)"
  elif [[ $rc = 127 && ! -f $models/$path ]]; then status="model missing"
  elif grep -q 'cannot load' "$log"; then status="refused"
  else status="failed (exit $rc)"
  fi
  msg=$(messages "$log" || true)
  [[ -n $msg || $rc = 0 ]] || msg=$(grep -v '^$' "$log" | tail -n 2 | cut -c1-300 | paste -sd' ' -)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$path" "$features" "$rc" "$status" "$wall" \
    "${render_s:--}" "${tris:--}" "$msg" >>"$tsv"
  printf '%-28s %-10s exit %-3s %6s s  %s\n' "$name" "${status%% *}" "$rc" "$wall" "${msg:0:110}"

  if [[ $sheet = 1 ]]; then
    # tile: the reference screenshot (left) and the render (right), 160 px high each, labelled below.
    dir=${path%%/*}
    ref=""
    for f in ${references:+"$references/$name.png"} "$models/$dir/screenshot/screenshot.png" "$models/$dir/screenshot/screenshot.jpg" \
      "$models/$dir/screenshot/screenshot.gif" "$models/$dir/screenshot.png" "$models/$dir/screenshot.jpg"; do
      [[ -f $f ]] && { ref=$f; break; }
    done
    h=160
    if [[ -n $ref ]]; then
      convert -quiet "${ref}[0]" -resize "x$h" -background white -flatten "$out/tiles/$name.ref.png"
    else
      convert -quiet -size "${h}x$h" xc:'#dddddd' "${font[@]}" -pointsize 14 -gravity center -annotate 0 'no reference' \
        "$out/tiles/$name.ref.png"
    fi
    if [[ $status = rendered ]]; then
      convert -quiet "$png" -resize "x$h" "$out/tiles/$name.render.png"
    else
      convert -quiet -size "${h}x$h" xc:'#552222' -fill white "${font[@]}" -pointsize 13 -gravity center \
        -annotate 0 "$(echo "$status" | fold -w 20)" "$out/tiles/$name.render.png"
    fi
    convert -quiet "$out/tiles/$name.ref.png" -size 4x$h xc:white "$out/tiles/$name.render.png" +append \
      "$out/tiles/$name.png"
  fi
done <"$list"

# The markdown table.
python3 - "$tsv" "$out/gallery.md" "$vkmc" "$models" "$width" "$spp" "${extra[*]:-}" <<'EOF'
import csv, sys
tsv, md, vkmc, models, width, spp, extra = sys.argv[1:]
rows = list(csv.DictReader(open(tsv), delimiter="\t"))
count = lambda s: sum(1 for r in rows if r["status"].startswith(s))
with open(md, "w") as f:
    f.write(f"# glTF gallery\n\n`{vkmc}` on `{models}`, {width} px wide, {spp} spp{(' ' + extra) if extra else ''}.\n\n")
    f.write(f"{len(rows)} models: {count('rendered')} rendered, {count('refused')} refused, "
            f"{len(rows) - count('rendered') - count('refused')} failed, timed out or missing.\n\n")
    f.write("| model | features | outcome | exit | seconds (wall / render) | messages |\n|---|---|---|---|---|---|\n")
    for r in rows:
        msg = r["messages"].replace("|", "\\|")
        f.write(f"| {r['name']} | {r['features']} | {r['status']} | {r['rc']} | {r['wall_s']} / {r['render_s']} | {msg} |\n")
print(f"{len(rows)} models: {count('rendered')} rendered, {count('refused')} refused")
EOF

if [[ $sheet = 1 && $n -gt 0 ]]; then
  args=()
  while IFS=$'\t' read -r name _ _ _ status _; do
    [[ $name = name ]] && continue
    args+=(-label "$name: ${status%% (*}" "$out/tiles/$name.png")
  done <"$tsv"
  montage -quiet "${font[@]}" -pointsize 13 "${args[@]}" -tile 5x -geometry +6+6 -background white \
    -depth 8 "$out/contact_sheet.png"
  # a small copy (half size, 128 colours) that may go into docs/journal/img/
  convert -quiet "$out/contact_sheet.png" -resize 50% +dither -colors 128 "$out/contact_sheet_small.png"
  echo "contact sheet: $out/contact_sheet.png (left: reference screenshot, right: vkmc), small: $out/contact_sheet_small.png"
fi
echo "table: $out/gallery.md, raw: $tsv"
