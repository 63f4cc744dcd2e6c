# Sourced by the Lottie tests: pages that play a Lottie file in lottie-web
# (the vendored, pinned vendor/lottie-web, SVG renderer). Each page writes
# what happened into <pre id="result">: "ok" or the errors (lottie-web
# catches what fails while it draws and says so only in an event), and for
# the timing page the figures as JSON. Loading from animationData completes
# inside loadAnimation (no images or fonts), so everything runs before the
# page's load event, when Chromium takes its screenshot or dumps the DOM.
#   lottie_grid_page OUT.html ANIM.json COLS CELL FRAME...
#     one instance per cell, each seeked with goToAndStop(FRAME, true)
#   lottie_timing_page OUT.html ANIM.json REPEAT
#     one instance at the animation's size; every frame in turn, REPEAT
#     passes, timed: goToAndStop alone, and with the style and layout it
#     causes (getBoundingClientRect); median, 90th percentile and largest ms
lottie_player="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/vendor/lottie-web/lottie_svg.min.js"

lottie_page_start() {
  local out=$1 json=$2
  { printf 'window.ANIM = '; cat "$json"; printf ';\n'; } > "${out%.html}.anim.js"
  echo '<!DOCTYPE html><html><head><style>body{margin:0;background:#fff}#grid{display:grid}#grid>div{overflow:hidden}#result{display:none}</style></head><body>'
  echo '<div id="grid"></div><pre id="result"></pre>'
  echo "<script src=\"file://$lottie_player\"></script><script src=\"$(basename "${out%.html}").anim.js\"></script>"
  echo '<script>
const errors = [];
function load(container) {
  const anim = lottie.loadAnimation({container, renderer: "svg", loop: false, autoplay: false,
                                     animationData: JSON.parse(JSON.stringify(window.ANIM))});
  anim.addEventListener("error", (e) => errors.push(e.nativeError ? e.nativeError.message : e.type));
  if (!anim.isLoaded) errors.push("lottie-web had not loaded the animation when loadAnimation returned");
  return anim;
}
function cell(w, h) {
  const div = document.createElement("div");
  div.style.width = w + "px";
  div.style.height = h + "px";
  document.getElementById("grid").appendChild(div);
  return div;
}'
}

lottie_grid_page() {
  local out=$1 json=$2 cols=$3 size=$4
  shift 4
  {
    lottie_page_start "$out" "$json"
    echo "document.getElementById('grid').style.gridTemplateColumns = 'repeat($cols, ${size}px)';"
    echo "for (const frame of [$(IFS=,; echo "$*")]) load(cell($size, $size)).goToAndStop(frame, true);"
    echo 'document.getElementById("result").textContent = errors.length ? errors.join("\n") : "ok";'
    echo '</script></body></html>'
  } > "$out"
}

lottie_timing_page() {
  local out=$1 json=$2 repeat=$3
  {
    lottie_page_start "$out" "$json"
    echo "const div = cell(ANIM.w, ANIM.h);"
    echo "const t_load = performance.now();"
    echo "const anim = load(div);"
    echo "const load_ms = performance.now() - t_load;"
    echo "const seek = [], layout = [];"
    echo "for (let pass = 0; pass < $repeat; ++pass)"
    echo '  for (let f = 0; f < ANIM.op - ANIM.ip; ++f) {
    const t0 = performance.now();
    anim.goToAndStop(f, true);
    const t1 = performance.now();
    div.getBoundingClientRect();
    const t2 = performance.now();
    seek.push(t1 - t0);
    layout.push(t2 - t0);
  }
function stats(times) {
  times.sort((a, b) => a - b);
  const at = (q) => times[Math.min(times.length - 1, Math.floor(q * times.length))];
  return {median_ms: at(0.5), p90_ms: at(0.9), max_ms: times[times.length - 1]};
}
document.getElementById("result").textContent = errors.length ? errors.join("\n") :
  JSON.stringify({load_ms, calls: seek.length, goToAndStop: stats(seek), with_layout: stats(layout)});
</script></body></html>'
  } > "$out"
}

# The text of <pre id="result"> in a dumped DOM.
lottie_result() {
  sed -n '/<pre id="result">/{:a;/<\/pre>/!{N;ba};s/.*<pre id="result">//;s/<\/pre>.*//;p;q}'
}
