#!/bin/bash
# `compare report`, `reference` and `summary` on real renders of scenes/example.xml, and
# the bad-input rule of every subcommand: one line naming the files, exit 2, no file left.
#   report_cli.sh RAYTRACER COMPARE SOURCE_DIR SCENES_DIR WORK_DIR
set -u
raytracer=$1 compare=$2 source=$3 scenes=$4 work=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect_in TEXT WORD...: every WORD occurs in TEXT.
expect_in() {
  local text=$1 w
  shift
  for w in "$@"; do [[ $text == *"$w"* ]] || fail "'$w' missing from: $text"; done
}

render() {  # render DIR SCENE SEED SCALE
  mkdir -p "$1"
  "$raytracer" "$2" --device cpu --seed "$3" --resolution-scale "$4" --spp 8 --moments \
    --output-dir "$1" >"$1.log" 2>&1 || { echo "render failed: $(tail -1 "$1.log")"; exit 1; }
}
scene=$source/scenes/example.xml
# The same scene with the area light 30 % brighter: a bias that equal seeds show at once.
sed 's|<Radiance>6000 6000 6000</Radiance>|<Radiance>7800 7800 7800</Radiance>|' "$scene" >bright.xml
grep -q 7800 bright.xml || { echo "bright.xml: the area light's Radiance was not found"; exit 1; }
render s1 "$scene" 1 0.1
render s2 "$scene" 2 0.1
render bright "$work/bright.xml" 1 0.1
render small "$scene" 1 0.05
a=s1/example.png b=s2/example.png

# Identical inputs say so.
out=$("$compare" paired $a $a) || fail "paired A A: exit $?"
expect_in "$out" "identical" "verdict: PASS"
[[ $out == *"tests 0"* ]] && fail "paired A A still reports its empty tests: $out"
out=$("$compare" welch $a $a) || fail "welch A A: exit $?"
expect_in "$out" "identical"

# The three verdicts of a report, and the difference summary of plain PNGs.
report() {  # report A B OUT: prints the verdict line of the page
  "$compare" report "$1" "$2" --out "$3" >"$3.log" 2>&1 || fail "report $1 $2: exit $?"
  [ -s "$3" ] || fail "report $1 $2: no $3"
  grep -o '<p id="verdict"[^>]*>[^<]*' "$3" | sed 's/.*>//'
}
expect_in "$(report $a $a same.html)" "identical"
expect_in "$(report $a $b noise.html)" "within noise" "welch"
expect_in "$(report $a bright/example.png biased.html)" "biased" "paired"
mkdir -p plain && cp $a plain/a.png && cp $b plain/b.png
expect_in "$(report plain/a.png plain/b.png plain.html)" "differ (no moments" \
  "largest difference" "of pixels differ"
mkdir -p dir && "$compare" report $a $b --out dir/ >/dev/null && [ -s dir/report.html ] ||
  fail "report --out DIR/ wrote no DIR/report.html"

# A size mismatch: one line naming both files and sizes, exit 2, for every subcommand.
c=small/example.png
for cmd in "welch $a $c" "paired $a $c" "exact $a $c" "diff $a $c" "report $a $c --out x.html" \
  "reference $a $c --criterion hw12"; do
  # shellcheck disable=SC2086
  err=$("$compare" $cmd 2>&1 >/dev/null)
  rc=$?
  [ $rc -eq 2 ] || fail "$cmd: exit $rc, expected 2"
  [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "$cmd: more than one line: $err"
  expect_in "$err" "$a is 48x36" "$c is 24x18"
  [[ $err == *diff_images* || $err == *check_same_size* ]] && fail "$cmd: internal name: $err"
done
[ -e x.html ] && fail "report of mismatched sizes left x.html"
err=$("$compare" diff $a $a --moments small/example.moments.exr 2>&1 >/dev/null)
[ $? -eq 2 ] || fail "diff --moments of another size: not exit 2"
expect_in "$err" "$a is 48x36" "small/example.moments.exr is 24x18"

# Bad input to report: an unwritable page, a missing file.
err=$("$compare" report $a $b --out /nonexistent/dir/r.html 2>&1)
[ $? -eq 2 ] || fail "report to /nonexistent: not exit 2"
expect_in "$err" "/nonexistent/dir/r.html"
err=$("$compare" report $a absent.png --out r.html 2>&1)
[ $? -eq 2 ] || fail "report of absent.png: not exit 2"
expect_in "$err" "absent.png"
[ -e r.html ] && fail "a failed report left r.html"

# reference: the criterion is looked up by the reference's path; a course image passes
# against itself and fails against a render of another scene of its size (when present).
ref=$scenes/hw1/reference/simple.png
if [ -f "$ref" ]; then
  out=$("$compare" reference "$ref" "$ref") || fail "reference REF REF: exit $?"
  expect_in "$out" "hw1.simple in" "identical 100.000 %" "PASS (criterion hw12)"
  other=$scenes/hw1/reference/two_spheres.png
  out=$("$compare" reference "$other" "$ref")
  [ $? -eq 1 ] || fail "two_spheres against simple's reference: not exit 1: $out"
  expect_in "$out" "FAIL (criterion hw12)"
  out=$("$compare" reference "$other" "$ref" --criterion block:255)  # Overrides the list.
  expect_in "$out" "criterion block:255 (--criterion)" "(criterion block)"
else
  echo "note: $ref is not present: reference against a course image not checked"
fi
err=$("$compare" reference $a $a 2>&1)
[ $? -eq 2 ] || fail "reference of an image not in the list: not exit 2"
expect_in "$err" "is not a reference image of" "--criterion"
err=$("$compare" reference $a $a --criterion hw9 2>&1)
[ $? -eq 2 ] || fail "reference --criterion hw9: not exit 2"
expect_in "$err" "unknown kind 'hw9'"
out=$("$compare" reference $a $b --criterion hw3)
[ $? -le 1 ] || fail "reference --criterion hw3: exit $?"
expect_in "$out" "(criterion hw3)"

# summary: a PNG with its moments, a moment file, a missing file.
out=$("$compare" summary $a) || fail "summary: exit $?"
expect_in "$out" "48x36, 8-bit RGB PNG" "NaN 0, Inf 0" "samples per pixel: min 8, mean 8, max 8"
out=$("$compare" summary s1/example.moments.exr) || fail "summary of moments: exit $?"
expect_in "$out" "48x36, moment file" "8 spp, seed 1"
err=$("$compare" summary absent.png 2>&1)
[ $? -eq 2 ] || fail "summary absent.png: not exit 2"
expect_in "$err" "absent.png"

[ $failures -eq 0 ] && echo "PASS" && exit 0
echo "$failures failure(s)"
exit 1
