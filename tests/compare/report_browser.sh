#!/bin/bash
# A `compare report` page opened in headless Chromium: every image decoded (the page's own
# script counts them into #load-check after the load event), the verdict shown, and a
# screenshot that is not blank. A copy with one image corrupted must count one image
# short, so the check cannot pass by itself. Skipped (77) without chromium.
#   report_browser.sh RAYTRACER COMPARE SOURCE_DIR WORK_DIR
set -u
raytracer=$1 compare=$2 source=$3 work=$4
browser=$(command -v chromium || command -v chromium-browser) || {
  echo "SKIP: chromium is not installed (tools/install-deps.sh installs it)"
  exit 77
}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export HOME=$work  # Chromium's profile and crash files stay in the work directory.
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
chrome() {  # chrome ARGS... URL
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --user-data-dir="$work/profile" \
    --virtual-time-budget=5000 "$@" 2>>chromium.log
}

scene=$source/scenes/example.xml
sed 's|<Radiance>6000 6000 6000</Radiance>|<Radiance>7800 7800 7800</Radiance>|' "$scene" >bright.xml
for run in "a $scene" "b $work/bright.xml"; do
  set -- $run
  mkdir -p "$1"
  "$raytracer" "$2" --device cpu --seed 1 --resolution-scale 0.2 --spp 8 --moments \
    --output-dir "$1" >"$1.log" 2>&1 || { echo "render failed: $(tail -1 "$1.log")"; exit 1; }
done
"$compare" report a/example.png b/example.png --out report.html >report.log 2>&1 ||
  { echo "report failed: $(cat report.log)"; exit 1; }
images=$(grep -o '<img ' report.html | wc -l)
[ "$images" -ge 8 ] || fail "the page has $images images: expected A, B, two maps, two bars, tiles"

# check PAGE EXPECTED: the DOM after load says EXPECTED of the page's images were decoded.
check() {
  local dom
  dom=$(chrome --dump-dom "file://$work/$1")
  local loaded
  loaded=$(printf '%s' "$dom" | grep -o 'images loaded: [0-9]* of [0-9]*')
  [ "$loaded" = "images loaded: $2 of $images" ] ||
    fail "$1: '${loaded:-no load-check line}', expected 'images loaded: $2 of $images'"
  printf '%s' "$dom" | grep -q '<p id="verdict" class="verdict biased"[^>]*>biased here: ' ||
    fail "$1: the verdict 'biased here' is not in the DOM"
}
check report.html "$images"
# One image's PNG signature broken: the browser cannot decode it, and the check must see it.
sed '0,/base64,iVBORw0KGgo/s//base64,AAAAAAAAAAA/' report.html >broken.html
check broken.html $((images - 1))

chrome --screenshot="$work/shot.png" --window-size=1400,900 "file://$work/report.html" >/dev/null
if [ -s shot.png ]; then
  # A page that rendered shows more than one grey level in its red channel.
  range=$("$compare" summary shot.png | grep -o 'R: range \[[0-9]*, [0-9]*\]')
  [[ -n $range && $range != "R: range [255, 255]" && $range != "R: range [0, 0]" ]] ||
    fail "shot.png looks blank: $range"
else
  fail "no screenshot written"
fi

[ $failures -eq 0 ] && echo "PASS ($images images loaded, verdict shown, screenshot $work/shot.png)" && exit 0
echo "$failures failure(s); chromium's messages: $work/chromium.log"
exit 1
