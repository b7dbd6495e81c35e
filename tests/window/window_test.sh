#!/usr/bin/env bash
# The demo's window as a user drives it, under Xvfb with keys from xdotool:
# hide and show the overlay, take over the camera and fly it forward (two
# screenshots that must differ), switch backend twice at run time, quit with
# Esc. The run is under the validation layer: any message fails it.
#   window_test.sh DEMO OUTPUT_DIR
# Exits 77 (skipped) without Xvfb or xdotool, saying which is missing.
set -u
demo="$(realpath "$1")"
out="$2"
for tool in Xvfb xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIP: $tool is not installed (Debian packages xvfb and xdotool; ./tessera test installs them)"
    exit 77
  fi
done
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1

# Xvfb picks a free display itself and says which once it accepts clients
# (-displayfd): two runs starting together (two checkouts' suites on one
# machine) can no longer both take the number that looked free.
: >display.txt
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>display.txt >xvfb.log 2>&1 &
xvfb=$!
demo_pid=""
cleanup() {
  [ -n "$demo_pid" ] && kill "$demo_pid" 2>/dev/null
  kill "$xvfb" 2>/dev/null
  wait 2>/dev/null
}
trap cleanup EXIT
for _ in $(seq 100); do [ -s display.txt ] && break; sleep 0.1; done
[ -s display.txt ] || { echo "FAIL: Xvfb did not start"; cat xvfb.log; exit 1; }
export DISPLAY=":$(head -n 1 display.txt)"

"$demo" --window --validation --backend r2vb --scene terrain --width 480 --height 270 --frames 1000000 \
  >demo.log 2>&1 &
demo_pid=$!

wid=""
for _ in $(seq 1200); do
  wid=$(xdotool search --name '^Tessera$' 2>/dev/null | head -n 1)
  [ -n "$wid" ] && break
  kill -0 "$demo_pid" 2>/dev/null || break
  sleep 0.1
done
[ -n "$wid" ] || { echo "FAIL: no window named Tessera appeared"; cat demo.log; exit 1; }
# Keys go to the window under the pointer (no window manager here).
xdotool mousemove --window "$wid" 240 200
# Waits for a line in the log: the demo has handled the key before the next.
await() {
  for _ in $(seq 600); do
    grep -q -- "$1" demo.log && return 0
    kill -0 "$demo_pid" 2>/dev/null || break
    sleep 0.1
  done
  echo "FAIL: the demo never logged \"$1\""
  cat demo.log
  exit 1
}
await "backend r2vb on"
sleep 1
xdotool key F1;  await "overlay hidden"
xdotool key F1;  await "overlay shown"
xdotool key Tab; await "camera: free"
xdotool key F12; await "wrote tessera-screenshot-"
first=$(grep -o "tessera-screenshot-[0-9]*.png" demo.log | head -n 1)
xdotool keydown w; sleep 1.5; xdotool keyup w
await "camera at --camera"
xdotool key F12
for _ in $(seq 600); do [ "$(grep -c 'wrote tessera-screenshot-' demo.log)" -ge 2 ] && break; sleep 0.1; done
second=$(grep -o "tessera-screenshot-[0-9]*.png" demo.log | sed -n 2p)
[ -n "$second" ] || { echo "FAIL: the second screenshot was not written"; cat demo.log; exit 1; }
xdotool key 2; await "switched backend r2vb -> streamout"
xdotool key 3; await "switched backend streamout -> hulldomain"
sleep 1
xdotool key Escape
for _ in $(seq 600); do kill -0 "$demo_pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$demo_pid" 2>/dev/null; then echo "FAIL: Esc did not end the run"; cat demo.log; exit 1; fi
wait "$demo_pid"
code=$?
demo_pid=""
cat demo.log
[ "$code" -eq 0 ] || { echo "FAIL: the demo exited with $code"; exit 1; }
grep -q "validation messages: 0" demo.log || { echo "FAIL: validation messages"; exit 1; }
if cmp -s "$first" "$second"; then
  echo "FAIL: $first and $second are the same picture: W did not move the camera"
  exit 1
fi
echo "PASS: overlay toggled, camera moved ($first -> $second), backend switched twice, 0 validation messages"
