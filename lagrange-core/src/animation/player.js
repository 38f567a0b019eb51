// The player of lagrange's animations: draws a recorded trajectory of a mechanism on a canvas.
// Written for lagrange, with no dependencies: the page that embeds it needs no network.
//
// The page holds the recording as JSON in <script id="lagrange-data" type="application/json">,
// and this script mounts a player on #lagrange-animation. A recording lists the items drawn
// (bodies, family members, marked and fixed points), the links between them, the bodies each
// constraint names, the trails, and the frames: `stride` numbers per frame, an item's `width`
// numbers from its `offset` — a position (2 or 3), a planar body's position and angle, or a
// spatial body's position and the three columns of its rotation matrix.
"use strict";
(function () {
  const PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"];
  const AXIS_COLOURS = ["#e41a1c", "#4daf4a", "#377eb8"];
  const CONSTRAINT_COLOURS = ["#ff7f0e", "#9467bd", "#17becf", "#8c564b"];
  const BACKGROUND = "#ffffff";
  const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4, 10];

  function element(tag, attributes, parent) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
  }

  function rgb(hex) {
    return [1, 3, 5].map(i => parseInt(hex.slice(i, i + 2), 16));
  }

  class Player {
    constructor(root, scene) {
      this.scene = scene;
      this.n = scene.times.length;
      this.items = scene.items.map((item, i) =>
        Object.assign({ index: i, colour: PALETTE[i % PALETTE.length] }, item));
      this.byName = new Map(this.items.map(item => [item.name, item]));
      this.frame = 0;
      this.time = scene.times[0];
      this.playing = this.n > 1;
      this.speed = 1;
      // The camera of a spatial drawing: turned about the vertical (z) axis, then tilted.
      this.yaw = -0.6;
      this.pitch = 0.45;
      this.zoom = 1;
      this.pan = [0, 0];
      this.drawn = {};
      this.build(root);
      this.resize();
      window.addEventListener("resize", () => { this.resize(); this.draw(this.frame); });
      requestAnimationFrame(now => this.tick(now));
    }

    build(root) {
      root.classList.add("lagrange-player");
      this.canvas = element("canvas", { class: "lagrange-canvas" }, root);
      this.context = this.canvas.getContext("2d");
      const bar = element("div", { class: "lagrange-controls" }, root);
      this.button = element("button", { type: "button" }, bar);
      this.button.addEventListener("click", () => this.toggle());
      this.slider = element("input", {
        type: "range", min: "0", max: String(Math.max(this.n - 1, 0)), step: "1", value: "0",
        "aria-label": "time",
      }, bar);
      this.slider.addEventListener("input", () => {
        this.playing = false;
        this.show(Number(this.slider.value));
      });
      const speed = element("select", { "aria-label": "speed" }, bar);
      for (const s of SPEEDS) {
        const option = element("option", { value: String(s) }, speed);
        option.textContent = s + "×";
        if (s === 1) option.selected = true;
      }
      speed.addEventListener("change", () => { this.speed = Number(speed.value); });
      this.clock = element("span", { class: "lagrange-clock" }, bar);
      const hint = element("span", { class: "lagrange-hint" }, bar);
      hint.textContent = this.scene.dim === 3 ? "drag to turn, wheel to zoom"
        : "drag to move, wheel to zoom";
      this.legend(root);
      this.interact();
    }

    legend(root) {
      const legend = element("div", { class: "lagrange-legend" }, root);
      for (const item of this.items) {
        const entry = element("span", {}, legend);
        const swatch = element("i", {}, entry);
        swatch.style.background = item.colour;
        entry.appendChild(document.createTextNode(item.name));
      }
      this.scene.constraints.forEach((c, j) => {
        const entry = element("span", {}, legend);
        const swatch = element("i", { class: "lagrange-ring" }, entry);
        swatch.style.borderColor = CONSTRAINT_COLOURS[j % CONSTRAINT_COLOURS.length];
        entry.appendChild(document.createTextNode(c.name));
      });
    }

    interact() {
      let last = null;
      this.canvas.addEventListener("pointerdown", e => {
        last = [e.clientX, e.clientY];
        this.canvas.setPointerCapture(e.pointerId);
      });
      this.canvas.addEventListener("pointerup", () => { last = null; });
      this.canvas.addEventListener("pointermove", e => {
        if (!last) return;
        const [dx, dy] = [e.clientX - last[0], e.clientY - last[1]];
        last = [e.clientX, e.clientY];
        if (this.scene.dim === 3 && !e.shiftKey) {
          this.yaw += dx * 0.01;
          this.pitch = Math.max(-1.5, Math.min(1.5, this.pitch + dy * 0.01));
        } else {
          const ratio = window.devicePixelRatio || 1;
          this.pan = [this.pan[0] + dx * ratio, this.pan[1] + dy * ratio];
        }
        this.draw(this.frame);
      });
      this.canvas.addEventListener("wheel", e => {
        e.preventDefault();
        this.zoom *= Math.exp(-e.deltaY * 0.001);
        this.draw(this.frame);
      }, { passive: false });
    }

    resize() {
      const ratio = window.devicePixelRatio || 1;
      const width = Math.max(200, Math.min(this.canvas.parentElement.clientWidth || 640, 960));
      const height = Math.round(width * 0.62);
      this.canvas.style.width = width + "px";
      this.canvas.style.height = height + "px";
      this.canvas.width = Math.round(width * ratio);
      this.canvas.height = Math.round(height * ratio);
      this.ratio = ratio;
    }

    toggle() {
      if (!this.playing && this.frame === this.n - 1) this.show(0);
      this.playing = !this.playing && this.n > 1;
      this.draw(this.frame);
    }

    tick(now) {
      const dt = this.last === undefined ? 0 : Math.min((now - this.last) / 1000, 0.1);
      this.last = now;
      if (this.playing) {
        const times = this.scene.times;
        this.time += dt * this.speed;
        if (this.time > times[this.n - 1]) this.time = times[0];
        const k = this.frameAt(this.time);
        if (k !== this.frame) this.draw(k);
      }
      requestAnimationFrame(next => this.tick(next));
    }

    // Shows frame k, with the clock at its time.
    show(k) {
      this.time = this.scene.times[k];
      this.draw(k);
    }

    // The last frame at or before time t (the first frame before it).
    frameAt(t) {
      const times = this.scene.times;
      let lo = 0;
      let hi = this.n - 1;
      if (t >= times[hi]) return hi;
      while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (times[mid] <= t) lo = mid; else hi = mid;
      }
      return lo;
    }

    // The dimension of an item's position.
    positionDim(item) {
      if (item.kind === "planar") return 2;
      if (item.kind === "spatial") return 3;
      if (item.kind === "fixed") return this.scene.dim;
      return item.width;
    }

    position(item, k) {
      if (item.kind === "fixed") return item.at.slice();
      const f = this.scene.frames;
      const base = k * this.scene.stride + item.offset;
      return [f[base], f[base + 1], this.positionDim(item) === 3 ? f[base + 2] : 0];
    }

    // The unit axes of a rigid body's frame in frame k, in world coordinates.
    axes(item, k) {
      const f = this.scene.frames;
      const base = k * this.scene.stride + item.offset;
      if (item.kind === "planar") {
        const [c, s] = [Math.cos(f[base + 2]), Math.sin(f[base + 2])];
        return [[c, s, 0], [-s, c, 0]];
      }
      return [0, 1, 2].map(j => [0, 1, 2].map(r => f[base + 3 + 3 * j + r]));
    }

    // World to canvas pixels: the plane with y up, or space seen by the turning camera.
    project(p) {
      const [lo, hi] = this.scene.extent;
      const centre = [0, 1, 2].map(i => (lo[i] + hi[i]) / 2);
      const [w, h] = [this.canvas.width, this.canvas.height];
      const d = [0, 1, 2].map(i => p[i] - centre[i]);
      let x;
      let y;
      let scale;
      if (this.scene.dim === 2) {
        const span = [Math.max(hi[0] - lo[0], 1e-12), Math.max(hi[1] - lo[1], 1e-12)];
        scale = 0.9 * Math.min(w / span[0], h / span[1]);
        [x, y] = [d[0], d[1]];
      } else {
        const radius = Math.max(Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2, 1e-12);
        scale = 0.45 * Math.min(w, h) / radius;
        const [cy, sy] = [Math.cos(this.yaw), Math.sin(this.yaw)];
        const [cp, sp] = [Math.cos(this.pitch), Math.sin(this.pitch)];
        const right = cy * d[0] - sy * d[1];
        const depth = sy * d[0] + cy * d[1];
        [x, y] = [right, d[2] * cp + depth * sp];
      }
      scale *= this.zoom;
      return [w / 2 + this.pan[0] + x * scale, h / 2 + this.pan[1] - y * scale];
    }

    line(points, colour, width, dash) {
      const c = this.context;
      c.beginPath();
      points.forEach((p, i) => {
        const [x, y] = this.project(p);
        if (i === 0) c.moveTo(x, y); else c.lineTo(x, y);
      });
      c.strokeStyle = colour;
      c.lineWidth = width * this.ratio;
      c.setLineDash(dash ? dash.map(v => v * this.ratio) : []);
      c.stroke();
      c.setLineDash([]);
    }

    disc(screen, radius, fill, stroke) {
      const c = this.context;
      c.beginPath();
      c.arc(screen[0], screen[1], radius * this.ratio, 0, 2 * Math.PI);
      if (fill) { c.fillStyle = fill; c.fill(); }
      if (stroke) { c.strokeStyle = stroke; c.lineWidth = 1.5 * this.ratio; c.stroke(); }
    }

    ground() {
      const [lo, hi] = this.scene.extent;
      const grey = "#d0d0d0";
      if (this.scene.dim === 2) {
        this.line([[lo[0] - 1e3 * (hi[0] - lo[0] + 1), 0, 0], [hi[0] + 1e3 * (hi[0] - lo[0] + 1), 0, 0]], grey, 1);
        this.line([[0, lo[1] - 1e3 * (hi[1] - lo[1] + 1), 0], [0, hi[1] + 1e3 * (hi[1] - lo[1] + 1), 0]], grey, 1);
        return;
      }
      // A grid on the plane z = 0 over the box the motion fills, and the world's axes.
      const steps = 8;
      for (let i = 0; i <= steps; i++) {
        const x = lo[0] + (hi[0] - lo[0]) * i / steps;
        const y = lo[1] + (hi[1] - lo[1]) * i / steps;
        this.line([[x, lo[1], 0], [x, hi[1], 0]], "#ececec", 1);
        this.line([[lo[0], y, 0], [hi[0], y, 0]], "#ececec", 1);
      }
      const axis = this.scene.axis;
      [[1, 0, 0], [0, 1, 0], [0, 0, 1]].forEach((e, j) =>
        this.line([[0, 0, 0], e.map(v => v * axis)], AXIS_COLOURS[j], 1, [4, 3]));
    }

    // Draws frame k and records where each item went (`drawn`), for the page's probe.
    draw(k) {
      this.frame = k;
      const c = this.context;
      c.fillStyle = BACKGROUND;
      c.fillRect(0, 0, this.canvas.width, this.canvas.height);
      this.ground();
      const at = this.items.map(item => this.position(item, k));
      const length = this.scene.trail_length;
      const from = length === null ? 0 : this.frameAt(this.scene.times[k] - length);
      for (const i of this.scene.trails) {
        const item = this.items[i];
        const path = [];
        for (let j = from; j <= k; j++) path.push(this.position(item, j));
        this.context.globalAlpha = 0.55;
        this.line(path, item.colour, 1.5);
        this.context.globalAlpha = 1;
      }
      for (const [a, b] of this.scene.links) this.line([at[a], at[b]], "#555555", 2.5);
      for (const item of this.items) {
        if (item.kind !== "planar" && item.kind !== "spatial") continue;
        this.axes(item, k).forEach((e, j) => this.line(
          [at[item.index], at[item.index].map((v, r) => v + this.scene.axis * e[r])],
          AXIS_COLOURS[j], 2));
      }
      this.scene.constraints.forEach((constraint, j) => {
        for (const i of constraint.items) {
          this.disc(this.project(at[i]), 11 + 3 * j, null, CONSTRAINT_COLOURS[j % CONSTRAINT_COLOURS.length]);
        }
      });
      this.drawn = {};
      for (const item of this.items) {
        const screen = this.project(at[item.index]);
        this.mark(item, screen);
        this.drawn[item.name] = { world: at[item.index], screen: screen };
      }
      this.clock.textContent = "t = " + this.scene.times[k].toFixed(3) + " s";
      this.slider.value = String(k);
      this.button.textContent = this.playing ? "Pause" : "Play";
    }

    mark(item, screen) {
      const c = this.context;
      switch (item.kind) {
        case "point": this.disc(screen, 4, BACKGROUND, item.colour); break;
        case "mark": this.disc(screen, 3.5, item.colour, null); break;
        case "fixed": {
          const r = 5 * this.ratio;
          c.fillStyle = item.colour;
          c.fillRect(screen[0] - r, screen[1] - r, 2 * r, 2 * r);
          break;
        }
        default: this.disc(screen, item.kind === "particle" ? 7 : 5.5, item.colour, null);
      }
    }

    // What a test reads back: whether frame 0 draws anything, how much the last frame differs
    // from it, and, when `request` names a body and a time, where the page draws that body then.
    probe(request) {
      const [playing, shown] = [this.playing, this.frame];
      this.playing = false;
      const [w, h] = [this.canvas.width, this.canvas.height];
      const background = rgb(BACKGROUND);
      this.draw(0);
      const first = this.context.getImageData(0, 0, w, h).data;
      let drawnPixels = 0;
      for (let i = 0; i < first.length; i += 4) {
        if (first[i] !== background[0] || first[i + 1] !== background[1]
          || first[i + 2] !== background[2]) drawnPixels++;
      }
      const other = this.n - 1;
      this.draw(other);
      const second = this.context.getImageData(0, 0, w, h).data;
      let changedPixels = 0;
      for (let i = 0; i < first.length; i += 4) {
        if (first[i] !== second[i] || first[i + 1] !== second[i + 1]
          || first[i + 2] !== second[i + 2]) changedPixels++;
      }
      const result = {
        title: this.scene.title, frames: this.n, size: [w, h], drawnPixels: drawnPixels,
        comparedFrame: other, changedPixels: changedPixels,
      };
      if (request && request.body !== undefined) result.position = this.probePosition(request);
      this.draw(shown);
      this.playing = playing;
      return result;
    }

    probePosition(request) {
      const item = this.byName.get(request.body);
      if (!item) return { error: "nothing drawn is named " + request.body };
      const k = this.frameAt(Number(request.t));
      this.draw(k);
      const d = this.drawn[item.name];
      const pixel = this.context.getImageData(Math.floor(d.screen[0]), Math.floor(d.screen[1]), 1, 1).data;
      return {
        body: item.name, frame: k, t: this.scene.times[k], world: d.world, screen: d.screen,
        pixel: [pixel[0], pixel[1], pixel[2]], colour: rgb(item.colour),
      };
    }
  }

  const players = [];

  function probe(request) {
    return {
      resources: performance.getEntriesByType("resource").map(e => e.name),
      players: players.map(p => p.probe(request || {})),
    };
  }

  function mount() {
    const data = document.getElementById("lagrange-data");
    const root = document.getElementById("lagrange-animation");
    if (!data || !root) return;
    // Inside another page (the gallery's index), which shows the title itself and is told the
    // height the player needs.
    const embedded = window.self !== window.top;
    if (embedded) document.body.classList.add("lagrange-embedded");
    players.push(new Player(root, JSON.parse(data.textContent)));
    if (embedded) {
      const height = Math.ceil(root.parentElement.getBoundingClientRect().bottom);
      window.parent.postMessage({ lagrangeHeight: height }, "*");
    }
    // `?probe=<JSON>`: the probe's result is written into the page, for a headless browser that
    // dumps the document.
    const query = new URLSearchParams(window.location.search);
    if (query.has("probe")) {
      const out = document.getElementById("lagrange-probe");
      out.textContent = JSON.stringify(probe(JSON.parse(query.get("probe") || "{}")));
    }
  }

  // A page that embeds this one (the gallery's index) asks by message and gets the probe back.
  window.addEventListener("message", event => {
    if (event.data && event.data.lagrangeProbe !== undefined && event.source) {
      event.source.postMessage({ lagrangeProbeResult: probe(event.data.lagrangeProbe) }, "*");
    }
  });

  window.LagrangeAnimation = { Player: Player, players: players, probe: probe };
  mount();
})();
