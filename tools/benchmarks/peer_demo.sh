#!/usr/bin/env bash
# tools/benchmarks/peer_demo.sh DEMO_DIR [ROUNDS] [WxH] [SECONDS]
#
# Frames per second of a peer water demo and of `vkwater view scenes/pool.json`, side by side on this
# machine at the same size (default 3 rounds, 800x600, 15 s of demo per round). The peer is Evan
# Wallace's WebGL Water (2011, MIT licence): a pool with a floating ball, a heightfield simulated on
# the GPU, caustics on the pool's walls from a refracted light mesh. It is not part of this
# repository: DEMO_DIR is a checkout of https://github.com/evanw/webgl-water (its index.html and
# scripts, unchanged). Each round, in turn:
# - the demo, in headless Chromium with WebGL on SwiftShader (the CPU, as lavapipe is for vkwater):
#   a copy of DEMO_DIR served on 127.0.0.1, its help panel hidden and its window's size set so that
#   its canvas is exactly WxH, and a script that counts the page's animation frames over SECONDS
#   after 3 s of warm-up and posts the rate back;
# - `vkwater view` at WxH under the default budget of a CPU device (66 ms), 200 frames;
# - `vkwater view` at WxH at the scene's own settings (no budget), 12 frames.
# The viewer's rate is 1000 over its median frame interval (its summary; warm-up frames left out).
# Prints the provenance line and a Markdown table of each rate's median over the rounds.
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] && [ -f "$1/index.html" ] && [ -f "$1/main.js" ] || {
  echo "usage: $0 DEMO_DIR [ROUNDS] [WxH] [SECONDS]: DEMO_DIR is a checkout of https://github.com/evanw/webgl-water" >&2
  exit 1
}
demo_dir=$1
rounds=${2:-3}
size=${3:-800x600}
seconds=${4:-15}
width=${size%x*}
height=${size#*x}
vk=${VKWATER:-build/tools/vkwater/vkwater}
[ -x "$vk" ] || { echo "peer_demo: build this tree first ($vk)" >&2; exit 1; }
command -v chromium >/dev/null || { echo "peer_demo: chromium is missing (tools/install-deps.sh installs it)" >&2; exit 1; }

source tools/benchmarks/provenance.sh
provenance_start

work=$(mktemp -d)
server_pid=
trap '[ -z "$server_pid" ] || kill "$server_pid" 2>/dev/null || true; rm -rf "$work"' EXIT
cp -r "$demo_dir" "$work/demo"

# The measuring snippet, added before </body>. The demo sizes its canvas from the window (its width
# less the help panel's and 20 px, its height), so the panel is hidden and the window's inner size
# is given as the canvas's plus those 20 px.
python3 - "$work/demo/index.html" "$width" "$height" "$seconds" <<'EOF'
import sys
path, width, height, seconds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
snippet = f"""<style>#help {{ display: none; }}</style>
<script>
Object.defineProperty(window, 'innerWidth', {{ get: function() {{ return {width + 20}; }} }});
Object.defineProperty(window, 'innerHeight', {{ get: function() {{ return {height}; }} }});
Object.defineProperty(window, 'devicePixelRatio', {{ get: function() {{ return 1; }} }});
(function() {{
  var warm = 3000, span = {seconds * 1000}, start = 0, frames = 0;
  function tick(t) {{
    if (!start) start = t;
    if (t - start > warm) frames++;
    if (t - start < warm + span) {{ requestAnimationFrame(tick); return; }}
    var info = gl.getExtension('WEBGL_debug_renderer_info');
    fetch('/result', {{ method: 'POST', body: JSON.stringify({{
      fps: frames / (span / 1000), width: gl.canvas.width, height: gl.canvas.height,
      renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER) }}) }});
  }}
  window.addEventListener('load', function() {{ requestAnimationFrame(tick); }});
}})();
</script>
</body>"""
text = open(path).read()
if "</body>" not in text:
    sys.exit("peer_demo: the demo's index.html has no </body>")
open(path, "w").write(text.replace("</body>", snippet, 1))
EOF

# One run of the demo: serves the copy, opens it, waits for the posted rate (JSON on one line).
demo_fps() {
  local port result
  port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  python3 - "$work/demo" "$port" > "$work/result.json" 2>/dev/null <<'EOF' &
import http.server, os, sys
class Handler(http.server.SimpleHTTPRequestHandler):
    def do_POST(self):
        body = self.rfile.read(int(self.headers.get("Content-Length", 0))).decode()
        self.send_response(204)
        self.end_headers()
        print(body, flush=True)
        os._exit(0)
    def log_message(self, *args):
        pass
os.chdir(sys.argv[1])
http.server.ThreadingHTTPServer(("127.0.0.1", int(sys.argv[2])), Handler).serve_forever()
EOF
  server_pid=$!
  sleep 0.5
  timeout $(( ${seconds%.*} + 60 )) chromium --headless=new --no-sandbox --use-angle=swiftshader \
    --enable-unsafe-swiftshader --disable-gpu-vsync --disable-frame-rate-limit \
    --user-data-dir="$work/profile" "http://127.0.0.1:$port/index.html" > "$work/chromium.log" 2>&1 &
  local browser=$!
  # The server exits when the rate arrives; the browser, at the latest, when its timeout ends.
  while kill -0 "$server_pid" 2>/dev/null && kill -0 "$browser" 2>/dev/null; do sleep 1; done
  kill "$server_pid" "$browser" 2>/dev/null || true
  wait "$server_pid" "$browser" 2>/dev/null || true
  server_pid=
  result=$(cat "$work/result.json")
  [ -n "$result" ] || { echo "peer_demo: the demo posted no rate (see $work/chromium.log)" >&2; exit 2; }
  echo "$result"
}

# One run of the viewer: the rate from its summary's median frame interval.
view_fps() {  # FRAMES ARGS...
  local frames=$1
  shift
  xvfb-run -a "$vk" view scenes/pool.json --width "$width" --height "$height" --frames "$frames" "$@" \
    > "$work/view.log" 2>&1
  awk '/^frames:/ { for (i = 1; i <= NF; ++i) if ($i == "median") { printf "%.3f\n", 1000 / $(i + 1); exit } }' \
    "$work/view.log"
}

renderer=
for round in $(seq "$rounds"); do
  json=$(demo_fps)
  python3 -c "import json, sys; r = json.loads(sys.argv[1]); assert (r['width'], r['height']) == ($width, $height), r; print(r['fps'])" \
    "$json" >> "$work/demo.fps"
  renderer=$(python3 -c "import json, sys; print(json.loads(sys.argv[1])['renderer'])" "$json")
  view_fps 200 --budget-ms 66 >> "$work/budget.fps"
  view_fps 12 >> "$work/own.fps"
done

source tools/benchmarks/median.sh
median_of() { printf '%.1f' "$(median < "$1")"; }
rates() { awk '{ printf "%s%.1f", (NR > 1 ? ", " : ""), $1 } END { print "" }' "$1"; }

provenance_line "$vk" "median of $rounds rounds; the demo's WebGL: $renderer"
echo
echo "| at ${width}x${height} | fps, median | fps, each round |"
echo "| --- | --- | --- |"
echo "| WebGL Water (2011), Chromium on SwiftShader | $(median_of "$work/demo.fps") | $(rates "$work/demo.fps") |"
echo "| \`vkwater view scenes/pool.json\`, budget 66 ms | $(median_of "$work/budget.fps") | $(rates "$work/budget.fps") |"
echo "| \`vkwater view scenes/pool.json\`, its own settings | $(median_of "$work/own.fps") | $(rates "$work/own.fps") |"
