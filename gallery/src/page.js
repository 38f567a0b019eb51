// The gallery's index. Each animation (an iframe) reports its height, and its frame is sized to it.
// With `?probe=<JSON>` in its address it asks every scene's animation (each
// in an iframe, written by lagrange's animation player) for its probe — `{scene: request}`, a
// request naming a body and a time — and writes the answers into #lagrange-probe, for a headless
// browser that dumps the document. Without it, this script does nothing.
"use strict";
(function () {
  // Each animation says how tall it is; its frame takes that height.
  window.addEventListener("message", event => {
    if (!event.data || typeof event.data.lagrangeHeight !== "number") return;
    for (const frame of document.querySelectorAll("iframe[data-scene]")) {
      if (frame.contentWindow === event.source) frame.style.height = (event.data.lagrangeHeight + 4) + "px";
    }
  });
  const query = new URLSearchParams(window.location.search);
  if (!query.has("probe")) return;
  const requests = JSON.parse(query.get("probe") || "{}");
  const frames = Array.from(document.querySelectorAll("iframe[data-scene]"));
  const answers = {};
  let written = false;
  function write() {
    if (written) return;
    written = true;
    document.getElementById("lagrange-probe").textContent = JSON.stringify({
      resources: performance.getEntriesByType("resource").map(e => e.name),
      scenes: answers,
    });
  }
  window.addEventListener("message", event => {
    const frame = frames.find(f => f.contentWindow === event.source);
    if (!frame || !event.data || event.data.lagrangeProbeResult === undefined) return;
    answers[frame.dataset.scene] = event.data.lagrangeProbeResult;
    if (Object.keys(answers).length === frames.length) write();
  });
  window.addEventListener("load", () => {
    for (const frame of frames) {
      frame.contentWindow.postMessage({ lagrangeProbe: requests[frame.dataset.scene] || {} }, "*");
    }
    // Whatever answered by then: a scene that did not is missing from the answers.
    setTimeout(write, 3000);
  });
})();
