#!/usr/bin/env bash
# Make docs/dietmaier-40-modes.png: the 40 real assembly modes of the `dietmaier` preset's
# home legs, one small render each (same camera), tiled 8 × 5 by ffmpeg.
# Run from the repository root after `cargo build --release`.
set -euo pipefail
stewart=${STEWART:-target/release/stewart}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$stewart" settings --preset dietmaier --as-coordinates > "$work/d.toml"
height=$(awk '/^home_height/ {print $3}' "$work/d.toml")
printf 'x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,%s,0,0,0\n' "$height" > "$work/home.csv"
"$stewart" solve --preset dietmaier --poses "$work/home.csv" | cut -d, -f7- > "$work/legs.csv"
"$stewart" fk --preset dietmaier --legs "$work/legs.csv" --assembly-modes > "$work/modes.csv"
mkdir "$work/frames"
tail -n +2 "$work/modes.csv" | while IFS=, read -r _row mode x y z roll pitch yaw _; do
  # A pose table of one pose held for a second: the scenario shows that mode alone.
  printf 't,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,%s,%s,%s,%s,%s,%s\n1,%s,%s,%s,%s,%s,%s\n' \
    "$x" "$y" "$z" "$roll" "$pitch" "$yaw" "$x" "$y" "$z" "$roll" "$pitch" "$yaw" > "$work/one.csv"
  { sed -n '1,/^\[trajectory\]/p' "$work/d.toml" | sed '$d'
    printf '[trajectory]\nkind = "pose_table"\nfile = "one.csv"\n'; } > "$work/one.toml"
  rm -rf "$work/out"
  "$stewart" render --scenario "$work/one.toml" --out "$work/out" --fps 1 --frames 0..1 \
    --size 400x400 --theme light --no-labels --camera 35,15,6.5 > /dev/null 2>&1
  cp "$work/out/frame_00000.png" "$work/frames/mode_$(printf %02d "${mode%.*}").png"
done
ffmpeg -loglevel error -y -framerate 1 -pattern_type glob -i "$work/frames/mode_*.png" \
  -vf "scale=200:200,tile=8x5,split[a][b];[a]palettegen=max_colors=128[p];[b][p]paletteuse=dither=none" \
  -frames:v 1 docs/dietmaier-40-modes.png
echo "wrote docs/dietmaier-40-modes.png"
