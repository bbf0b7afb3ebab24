#!/usr/bin/env bash
# Browser test of the demo gallery (headless Debian Chromium via playwright-core).
#
#   tests/browser/run.sh [OUT_DIR]          test a gallery scripts/gallery built (default out/gallery)
#   tests/browser/run.sh --fixture [DIR]    no C++ needed: make_fixture.py DIR, scripts/gallery DIR,
#                                           then the test (default DIR out/gallery-fixture)
#   tests/browser/run.sh --selftest [DIR]   --fixture, then checks that a broken glb makes both the
#                                           renderer and the browser test fail
# Screenshots go to OUT_DIR/screenshots/. Exits non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
mode=test dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --fixture) mode=fixture ;;
    --selftest) mode=selftest ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    -*) echo "tests/browser/run.sh: unknown option $1" >&2; exit 2 ;;
    *) dir=$1 ;;
  esac
  shift
done
. "$root/scripts/deps.sh"
. "$root/web/deps.sh"
cyclide_web_deps chromium

if [ "$mode" = test ]; then
  dir=${dir:-$root/out/gallery}
  exec node "$root/tests/browser/browser_test.mjs" "$dir"
fi

dir=${dir:-$root/out/gallery-fixture}
rm -rf "$dir"
python3 "$root/tests/browser/make_fixture.py" "$dir"
"$root/scripts/gallery" "$dir"
node "$root/tests/browser/browser_test.mjs" "$dir"
[ "$mode" = fixture ] && exit 0

echo "selftest: a broken glb must fail the renderer and the browser test"
bad="$dir-broken"
rm -rf "$bad"
cp -r "$dir" "$bad"
python3 "$root/tests/browser/make_fixture.py" "$bad" --broken torus
ok=1
if "$root/scripts/gallery" "$bad" >"$bad/selftest-render.log" 2>&1; then
  echo "selftest: FAIL scripts/gallery accepted a broken glb"; ok=0
else
  echo "selftest: ok   scripts/gallery rejected it: $(grep -m1 FAILED "$bad/selftest-render.log")"
fi
if node "$root/tests/browser/browser_test.mjs" "$bad" >"$bad/selftest-browser.log" 2>&1; then
  echo "selftest: FAIL the browser test passed a broken glb"; ok=0
else
  echo "selftest: ok   the browser test rejected it: $(grep -m1 -A1 '^FAIL' "$bad/selftest-browser.log" | tail -1 | sed 's/^ *//')"
fi
[ "$ok" = 1 ] && rm -rf "$bad"
if [ "$ok" = 1 ]; then echo "selftest: 2 passed, 0 failed"; else echo "selftest: failed (logs in $bad)"; exit 1; fi
