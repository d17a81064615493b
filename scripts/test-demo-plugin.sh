#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the Polyhedron demo plugin (demo/) against a build of CGAL's
# Polyhedron demo and smoke-tests it under Xvfb; exits 0 only when the smoke
# test passes.
#
#   1. installs the Debian packages (scripts/install-deps.sh, then Qt5, the CGAL
#      demo sources, Xvfb, ImageMagick), with sudo when not root;
#   2. unpacks the demo sources of libcgal-demo and builds only the demo
#      executable Polyhedron_3 and the OFF reader plugin (reused when present);
#   3. builds the plugin (demo/CMakeLists.txt) and the tool nonobtuse-remesh;
#   4. runs the demo under xvfb-run with demo/smoke_test.js.in: load a mesh,
#      certify it (the action), remesh, certify, decimate, save, screenshot,
#      quit; then certifies the saved file exactly with nonobtuse-remesh.
#
# Environment:
#   DEMO_BUILD_DIR  where everything is built (default: build-demo/ in the repo)
#   JOBS            parallel build jobs (default: nproc)
#   MESH            input mesh (default: data/meshes/pig.off)
#   RESOLUTION      remeshing resolution (default: 40)
#   SCREENSHOT      PNG written from the Xvfb screen (default: none; give a path,
#                   e.g. doc/demo_plugin.png, to write one)
#   SKIP_INSTALL=1  do not call apt-get
#   DEMO_TIMEOUT    seconds the demo may run (default: 900)
#   TOOL            an already built nonobtuse-remesh (default: build one)
set -euo pipefail

REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DEMO_BUILD_DIR=${DEMO_BUILD_DIR:-$REPO/build-demo}
JOBS=${JOBS:-$(nproc)}
MESH=${MESH:-$REPO/data/meshes/pig.off}
RESOLUTION=${RESOLUTION:-40}
SCREENSHOT=${SCREENSHOT:-}
DEMO_TIMEOUT=${DEMO_TIMEOUT:-900}
mkdir -p "$DEMO_BUILD_DIR"
DEMO_BUILD_DIR=$(cd "$DEMO_BUILD_DIR" && pwd)
MESH=$(cd "$(dirname "$MESH")" && pwd)/$(basename "$MESH")

log() { echo "test-demo-plugin: $*"; }
seconds() { date +%s; }
T0=$(seconds)

# 1. Packages.
DEMO_PACKAGES="libcgal-qt5-dev libcgal-demo qtbase5-dev libqt5opengl5-dev libqt5svg5-dev qtscript5-dev
  libtbb-dev libgl1-mesa-dri xvfb xauth x11-apps imagemagick"
if [ "${SKIP_INSTALL:-0}" != 1 ]; then
  "$REPO/scripts/install-deps.sh"
  missing=""
  for p in $DEMO_PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
  done
  if [ -n "$missing" ]; then
    SUDO=""
    if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
    log "installing$missing"
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
  fi
fi

# 2. The demo sources and the demo build tree.
SRC=$DEMO_BUILD_DIR/src/demo/Polyhedron
if [ ! -f "$SRC/CMakeLists.txt" ]; then
  TARBALL=$(dpkg -L libcgal-demo | grep '/demo\.tar\.gz$' | head -n 1 || true)
  if [ -z "$TARBALL" ] || [ ! -f "$TARBALL" ]; then
    echo "test-demo-plugin: no demo.tar.gz in the package libcgal-demo" >&2
    exit 1
  fi
  log "unpacking demo/Polyhedron from $TARBALL"
  mkdir -p "$DEMO_BUILD_DIR/src"
  tar -xzf "$TARBALL" -C "$DEMO_BUILD_DIR/src" demo/Polyhedron
fi
DEMO_TREE=$DEMO_BUILD_DIR/polyhedron
if [ ! -f "$DEMO_TREE/CGAL_polyhedron_demoConfig.cmake" ]; then
  log "configuring the Polyhedron demo in $DEMO_TREE"
  if ! cmake -S "$SRC" -B "$DEMO_TREE" -DCMAKE_BUILD_TYPE=Release >"$DEMO_BUILD_DIR/demo-configure.log" 2>&1; then
    tail -n 40 "$DEMO_BUILD_DIR/demo-configure.log" >&2
    exit 1
  fi
fi
log "building Polyhedron_3 and off_plugin (-j$JOBS; log: $DEMO_BUILD_DIR/demo-build.log)"
T1=$(seconds)
if ! cmake --build "$DEMO_TREE" --target Polyhedron_3 off_plugin -j"$JOBS" >"$DEMO_BUILD_DIR/demo-build.log" 2>&1; then
  tail -n 40 "$DEMO_BUILD_DIR/demo-build.log" >&2
  exit 1
fi
T2=$(seconds)

# 3. The plugin and the tool.
PLUGIN_TREE=$DEMO_BUILD_DIR/plugin
log "building the plugin in $PLUGIN_TREE"
if ! cmake -S "$REPO/demo" -B "$PLUGIN_TREE" -DCMAKE_BUILD_TYPE=Release \
  -DCGAL_polyhedron_demo_DIR="$DEMO_TREE" >"$DEMO_BUILD_DIR/plugin-configure.log" 2>&1; then
  tail -n 40 "$DEMO_BUILD_DIR/plugin-configure.log" >&2
  exit 1
fi
if ! cmake --build "$PLUGIN_TREE" -j"$JOBS" >"$DEMO_BUILD_DIR/plugin-build.log" 2>&1; then
  tail -n 60 "$DEMO_BUILD_DIR/plugin-build.log" >&2
  exit 1
fi
PLUGIN_SO=$(find "$PLUGIN_TREE" -maxdepth 2 -name 'libnonobtuse_remeshing_plugin.so' | head -n 1)
[ -n "$PLUGIN_SO" ] || { echo "test-demo-plugin: the plugin library was not built" >&2; exit 1; }
T3=$(seconds)
if [ -n "${TOOL:-}" ] && [ -x "$TOOL" ]; then
  log "using the tool $TOOL"
else
  TOOL_TREE=$DEMO_BUILD_DIR/tool
  log "building nonobtuse-remesh in $TOOL_TREE"
  if ! cmake -S "$REPO" -B "$TOOL_TREE" -DCMAKE_BUILD_TYPE=Release -DNONOBTUSE_BUILD_TESTS=OFF \
    -DNONOBTUSE_BUILD_BENCH=OFF -DNONOBTUSE_BUILD_EXAMPLES=OFF >"$DEMO_BUILD_DIR/tool-configure.log" 2>&1; then
    tail -n 40 "$DEMO_BUILD_DIR/tool-configure.log" >&2
    exit 1
  fi
  if ! cmake --build "$TOOL_TREE" --target nonobtuse-remesh -j"$JOBS" >"$DEMO_BUILD_DIR/tool-build.log" 2>&1; then
    tail -n 40 "$DEMO_BUILD_DIR/tool-build.log" >&2
    exit 1
  fi
  TOOL=$TOOL_TREE/bin/nonobtuse-remesh
fi
T4=$(seconds)

# 4. The smoke test.
SMOKE=$DEMO_BUILD_DIR/smoke
rm -rf "$SMOKE"
mkdir -p "$SMOKE/home"
OUTPUT=$SMOKE/remeshed.off
sed -e "s|@INPUT@|$MESH|g" -e "s|@OUTPUT@|$OUTPUT|g" -e "s|@RESOLUTION@|$RESOLUTION|g" \
  -e "s|@QUIT_MS@|6000|g" "$REPO/demo/smoke_test.js.in" >"$SMOKE/smoke_test.js"
SHOT_XWD=$SMOKE/screen.xwd
cat >"$SMOKE/session.sh" <<EOF
#!/usr/bin/env bash
# Runs inside xvfb-run: the demo in the background, a screenshot once the
# result is written and drawn, then waits for the demo to quit by itself.
cd "$SMOKE"
export HOME="$SMOKE/home" XDG_CONFIG_HOME="$SMOKE/home/.config" XDG_RUNTIME_DIR="$SMOKE/runtime"
mkdir -p -m 700 "$SMOKE/runtime"
export POLYHEDRON_DEMO_PLUGINS_PATH="$(dirname "$PLUGIN_SO")"
export LIBGL_ALWAYS_SOFTWARE=1
"$DEMO_TREE/Polyhedron_3" --no-autostart "$SMOKE/smoke_test.js" >"$SMOKE/demo.log" 2>&1 &
pid=\$!
for _ in \$(seq 1 $DEMO_TIMEOUT); do
  if [ -f "$OUTPUT" ] || ! kill -0 \$pid 2>/dev/null; then break; fi
  sleep 1
done
if [ -f "$OUTPUT" ] && kill -0 \$pid 2>/dev/null; then
  sleep 3
  xwd -root -silent -display "\$DISPLAY" >"$SHOT_XWD" || true
fi
if kill -0 \$pid 2>/dev/null && [ ! -f "$OUTPUT" ]; then
  echo "the demo did not finish within $DEMO_TIMEOUT s: stopping it" >>"$SMOKE/demo.log"
  kill \$pid
fi
for _ in \$(seq 1 60); do kill -0 \$pid 2>/dev/null || break; sleep 1; done
if kill -0 \$pid 2>/dev/null; then
  echo "the demo did not quit: stopping it" >>"$SMOKE/demo.log"
  kill \$pid
fi
wait \$pid
EOF
log "smoke test: $(basename "$MESH") at resolution $RESOLUTION under Xvfb (log: $SMOKE/demo.log)"
set +e
xvfb-run -a -s "-screen 0 1280x800x24" bash "$SMOKE/session.sh"
DEMO_RC=$?
set -e
T5=$(seconds)

failed=0
fail() { echo "test-demo-plugin: FAIL: $*" >&2; failed=1; }
grep -a "QtScript: SMOKE" "$SMOKE/demo.log" || true
grep -a "^nonobtuse_remeshing: " "$SMOKE/demo.log" | grep -v ": stage " || true
[ "$DEMO_RC" -eq 0 ] || fail "the demo exited with code $DEMO_RC"
grep -aq "QtScript: SMOKE DONE" "$SMOKE/demo.log" || fail "the script did not complete (see $SMOKE/demo.log)"
if grep -aq "QtScript: SMOKE FAIL" "$SMOKE/demo.log"; then fail "a check of the script failed"; fi
if grep -aq "ReferenceError\|Qt Script exception" "$SMOKE/demo.log"; then
  fail "the script raised an exception (a missing plugin or action?)"
fi
if [ -f "$OUTPUT" ]; then
  if "$TOOL" certify "$OUTPUT"; then
    log "the saved result certifies in [30, 90] degrees"
  else
    fail "the saved result $OUTPUT does not certify"
  fi
else
  fail "no result written to $OUTPUT"
fi
if [ -n "$SCREENSHOT" ]; then
  if [ -s "$SHOT_XWD" ]; then
    mkdir -p "$(dirname "$SCREENSHOT")"
    convert "xwd:$SHOT_XWD" -resize 1024x -colors 128 -strip "png8:$SCREENSHOT"
    log "screenshot: $SCREENSHOT ($(stat -c %s "$SCREENSHOT") bytes)"
  else
    fail "no screenshot taken"
  fi
fi

log "times: demo build $((T2 - T1)) s, plugin build $((T3 - T2)) s, tool build $((T4 - T3)) s, smoke test $((T5 - T4)) s, total $((T5 - T0)) s"
if [ "$failed" -ne 0 ]; then
  tail -n 30 "$SMOKE/demo.log" >&2
  exit 1
fi
log "smoke test passed"
exit 0
