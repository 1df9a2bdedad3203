// drivectl ui: the page's logic. Every drive action is a console command
// sent through POST /api/cmd; the telemetry samples come from GET /api/tel.
"use strict";

const $ = (id) => document.getElementById(id);
const COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];

// ---- console link ----------------------------------------------------------

const history = [];
let histPos = 0;

function logConsole(line, reply) {
  const log = $("console-log");
  let t = "> " + line + "\n";
  if (reply.error) {
    t += "link error: " + reply.error + "\n";
  } else {
    for (const l of reply.lines) t += l + "\n";
    t += reply.ok ? "OK\n" : "ERR " + reply.code + " " + reply.message + "\n";
  }
  log.textContent += t;
  log.scrollTop = log.scrollHeight;
}

// Sends one command line; resolves to {lines, ok, code, message} or {error}.
async function cmd(line, quiet) {
  let reply;
  try {
    const r = await fetch("/api/cmd", { method: "POST", body: line });
    reply = await r.json();
    $("link-state").textContent = "connected";
  } catch (e) {
    reply = { error: String(e) };
    $("link-state").textContent = "link lost";
  }
  if (!quiet) logConsole(line, reply);
  return reply;
}

// The drive's own refusal, in its words.
function errText(r) {
  return r.error ? "link error: " + r.error : "ERR " + r.code + " " + r.message;
}

function field(r, key) {
  for (const l of r.lines || []) {
    if (l.startsWith(key + ": ")) return l.slice(key.length + 2);
  }
  return null;
}

$("console-input").addEventListener("keydown", async (e) => {
  const inp = $("console-input");
  if (e.key === "ArrowUp" && histPos > 0) {
    inp.value = history[--histPos];
    e.preventDefault();
  } else if (e.key === "ArrowDown" && histPos < history.length) {
    histPos++;
    inp.value = histPos < history.length ? history[histPos] : "";
    e.preventDefault();
  } else if (e.key === "Enter") {
    const line = inp.value.trim();
    inp.value = "";
    if (!line) return;
    history.push(line);
    histPos = history.length;
    await cmd(line);
  }
});

// ---- plots -----------------------------------------------------------------

// The page shows the firmware's "Nm" as "N m"; other units as they are.
function unitText(u) {
  return u === "Nm" ? "N m" : u;
}

// Every plot on the page by its container: a plot follows its container's
// width when the window is resized, so that no plot is wider than its panel.
const plots = new Map();
const resizer = new ResizeObserver((entries) => {
  for (const e of entries) {
    const p = plots.get(e.target);
    const w = Math.floor(e.contentRect.width);
    if (p && w > 0 && w !== p.width) p.setSize({ width: w, height: p.height });
  }
});

// A plot in `el`: x axis `xLabel`, the series [{label, scale}], one y axis
// per entry of `yAxes` ([{scale, label}]: the first on the left with the
// grid, the others on the right), so that quantities of different units
// each get their own range.
function plotInto(el, o) {
  const old = plots.get(el);
  if (old) old.destroy();
  el.textContent = "";
  const scales = { x: Object.assign({ time: false }, o.xScale || {}) };
  const axes = [Object.assign({ label: o.xLabel }, o.xAxis || {})];
  o.yAxes.forEach((a, k) => {
    scales[a.scale] = {};
    axes.push({ scale: a.scale, label: a.label, side: k === 0 ? 3 : 1, grid: { show: k === 0 } });
  });
  const series = [{ label: o.xLabel }];
  o.series.forEach((x, k) => series.push({ label: x.label, scale: x.scale, stroke: COLORS[k % COLORS.length], width: o.lineWidth || 1.5 }));
  const p = new uPlot({
    width: Math.max(100, Math.floor(el.clientWidth)),
    height: o.height || 220,
    scales,
    series,
    axes,
  }, o.data, el);
  plots.set(el, p);
  resizer.observe(el);
  return p;
}

// One y axis per unit, in the order the units first appear.
function unitAxes(units) {
  return [...new Set(units)].map((u) => ({ scale: u, label: unitText(u) }));
}

// ---- live telemetry --------------------------------------------------------

const tel = { plot: null, channels: [], t: [], v: [], next: 0, paused: false, total: 0, running: false };

async function loadChannels() {
  const r = await cmd("tel list", true);
  const box = $("tel-channels");
  box.textContent = "";
  for (const l of r.lines || []) {
    const m = l.match(/^(\S+) \[([^\]]*)\] (.*)$/);
    if (!m) continue;
    const lab = document.createElement("label");
    lab.title = m[3];
    const cb = document.createElement("input");
    cb.type = "checkbox";
    cb.id = "tel-ch-" + m[1];
    cb.value = m[1];
    cb.dataset.unit = m[2];
    cb.checked = ["torque", "torque_ref", "i_q"].includes(m[1]);
    // A changed choice restarts a running stream with it.
    cb.onchange = () => { if (tel.running) startTel(); };
    lab.append(cb, " " + m[1] + " [" + unitText(m[2]) + "]");
    box.append(lab);
  }
}

function makeTelPlot(channels, units) {
  tel.plot = plotInto($("tel-plot"), {
    xLabel: "drive time [s]",
    series: channels.map((c, k) => ({ label: c + " [" + unitText(units[k]) + "]", scale: units[k] })),
    yAxes: unitAxes(units),
    data: [[], ...channels.map(() => [])],
    height: 300,
    lineWidth: 1,
  });
}

function showTelRunning(on) {
  tel.running = on;
  $("tel-run").textContent = on ? "stop" : "start";
}

async function startTel() {
  const boxes = [...document.querySelectorAll("#tel-channels input:checked")];
  const channels = boxes.map((b) => b.value);
  const units = boxes.map((b) => b.dataset.unit);
  const rate = $("tel-rate").value;
  let r;
  try {
    r = await fetch("/api/tel/start?rate=" + encodeURIComponent(rate) + "&channels=" + channels.join(","), { method: "POST" }).then((x) => x.json());
  } catch (e) {
    r = { error: String(e) };
  }
  logConsole("tel start " + rate + " " + channels.join(","), r);
  if (!r.ok) {
    $("tel-msg").textContent = errText(r);
    showTelRunning(false);
    return;
  }
  $("tel-msg").textContent = "streaming";
  tel.channels = channels;
  tel.t = [];
  tel.v = channels.map(() => []);
  tel.next = 0;
  tel.total = 0;
  makeTelPlot(channels, units);
  showTelRunning(true);
}

async function stopTel() {
  let r;
  try {
    r = await fetch("/api/tel/stop", { method: "POST" }).then((x) => x.json());
  } catch (e) {
    r = { error: String(e) };
  }
  logConsole("tel stop", r);
  $("tel-msg").textContent = r.ok ? "stopped" : errText(r);
  if (r.ok) showTelRunning(false);
}

$("tel-run").onclick = () => (tel.running ? stopTel() : startTel());
$("tel-rate").onchange = () => { if (tel.running) startTel(); };

$("tel-pause").onclick = () => {
  tel.paused = !tel.paused;
  $("tel-pause").textContent = tel.paused ? "resume" : "pause";
};

function download(name, text) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "text/csv" }));
  a.download = name;
  a.click();
}

// The samples in the rolling window as CSV.
function telCsv() {
  let s = "time_s," + tel.channels.join(",") + "\n";
  tel.t.forEach((t, i) => { s += t + "," + tel.v.map((col) => col[i]).join(",") + "\n"; });
  return s;
}
$("tel-export").onclick = () => download("telemetry.csv", telCsv());

async function pollTel() {
  try {
    const d = await fetch("/api/tel?since=" + tel.next).then((x) => x.json());
    if (d.channels.join(",") === tel.channels.join(",") && d.t.length) {
      tel.next = d.next;
      tel.total += d.t.length;
      for (let i = 0; i < d.t.length; i++) {
        tel.t.push(d.t[i]);
        d.v[i].forEach((x, k) => tel.v[k].push(x));
      }
      const win = Number($("tel-window").value) || 0.5;
      const last = tel.t[tel.t.length - 1];
      let cut = 0;
      while (cut < tel.t.length && tel.t[cut] < last - win) cut++;
      if (cut) {
        tel.t.splice(0, cut);
        tel.v.forEach((col) => col.splice(0, cut));
      }
      if (tel.plot && !tel.paused) tel.plot.setData([tel.t, ...tel.v]);
    }
    $("tel-points").textContent = tel.total;
    $("tel-lost").textContent = d.lost;
    $("tel-bad").textContent = d.bad;
  } catch (e) { /* the next poll retries */ }
  setTimeout(pollTel, 100);
}

// ---- status and faults -----------------------------------------------------

let busy = 0; // experiments in flight: the status poll waits for them

async function pollStatus() {
  if (!busy) {
    const r = await cmd("status", true);
    if (r.lines) $("status").textContent = r.lines.join("\n");
    const mode = field(r, "mode");
    if (mode) sweepRangeFor(mode);
    const f = await cmd("fault", true);
    if (f.lines) $("faults").textContent = f.lines.join("\n") + (f.ok ? "" : "\n" + errText(f));
    const h = await cmd("fault history", true);
    if (h.lines) $("fault-history").textContent = h.lines.join("\n");
  }
  setTimeout(pollStatus, 1000);
}

$("mode-set").onclick = async () => {
  const m = $("mode").value;
  const r = await cmd("mode " + m);
  if (r.ok) sweepRangeFor(m);
};
$("enable").onclick = () => cmd("enable");
$("disable").onclick = () => cmd("disable");
$("fault-clear").onclick = () => cmd("fault clear");

// ---- configuration ---------------------------------------------------------

let schema = [];

// The page's own check: a number, whole for integers, within the range.
function checkValue(p, text) {
  if (text.trim() === "" || !isFinite(Number(text))) return "not a number";
  const x = Number(text);
  if (p.integer && !Number.isInteger(x)) return "must be a whole number";
  if (x < p.min || x > p.max) return "out of range [" + p.min + ", " + p.max + "] " + p.unit;
  return null;
}

async function loadConfig() {
  const s = await cmd("config schema", true);
  if (!s.ok) { $("cfg-msg").textContent = errText(s); return; }
  schema = JSON.parse(s.lines[0]);
  const body = $("cfg-table").querySelector("tbody");
  body.textContent = "";
  for (const p of schema) {
    const tr = document.createElement("tr");
    const inp = document.createElement("input");
    inp.id = "cfg-" + p.name;
    const btn = document.createElement("button");
    btn.id = "cfg-set-" + p.name;
    btn.textContent = "set";
    const msg = document.createElement("span");
    msg.id = "cfg-msg-" + p.name;
    msg.className = "small";
    btn.onclick = async () => {
      const why = checkValue(p, inp.value);
      if (why) {
        msg.textContent = "refused: " + why;
        msg.className = "small refused";
        return;
      }
      const r = await cmd("config set " + p.name + " " + inp.value.trim());
      msg.textContent = r.ok ? "set" : errText(r);
      msg.className = "small " + (r.ok ? "accepted" : "refused");
    };
    const cells = [p.name, inp, p.unit, (p.integer ? "integer " : "") + p.min + " .. " + p.max + (p.gates_off ? ", gates off" : ""), btn, p.description];
    for (const c of cells) {
      const td = document.createElement("td");
      td.append(c);
      tr.append(td);
    }
    tr.children[4].append(" ", msg);
    body.append(tr);
  }
  await loadValues();
}

async function loadValues() {
  for (const p of schema) {
    const r = await cmd("config get " + p.name, true);
    const m = r.ok && r.lines[0] && r.lines[0].match(/= (\S+)/);
    if (m) $("cfg-" + p.name).value = m[1];
  }
}

$("cfg-reload").onclick = loadValues;
$("cfg-save").onclick = async () => {
  const r = await cmd("config save");
  $("cfg-msg").textContent = r.ok ? "saved" : errText(r);
};
$("cfg-reset").onclick = async () => {
  const r = await cmd("config reset");
  $("cfg-msg").textContent = r.ok ? "defaults restored" : errText(r);
  await loadValues();
};

// ---- experiments -----------------------------------------------------------

// `capture dump`'s CSV: t_ms, i_d, i_q, torque, torque_ref, sw, adc.
function parseDump(r) {
  const cols = [[], [], [], [], []];
  for (const l of r.lines.slice(1)) {
    const v = l.split(",").map(Number);
    for (let k = 0; k < 5; k++) cols[k].push(v[k]);
  }
  return cols;
}

async function waitCapture() {
  for (let k = 0; k < 600; k++) {
    const st = await cmd("capture status", true);
    if (!st.ok) return st;
    if (field(st, "capture") === "done") return cmd("capture dump", true);
    await new Promise((res) => setTimeout(res, 100));
  }
  return { error: "capture not complete after 60 s" };
}

// A record's torques on the left axis, its currents on the right: a
// 0.4 N m step drawn on the axis of 4 A of i_q would be a flat line.
function plotCapture(el, r) {
  const c = parseDump(r);
  plotInto(el, {
    xLabel: "time from trigger [ms]",
    series: [
      { label: "torque [N m]", scale: "Nm" },
      { label: "torque_ref [N m]", scale: "Nm" },
      { label: "i_d [A]", scale: "A" },
      { label: "i_q [A]", scale: "A" },
    ],
    yAxes: unitAxes(["Nm", "A"]),
    data: [c[0], c[3], c[4], c[1], c[2]],
  });
  el.dataset.points = c[0].length;
}

// The experiments share the drive's capture buffer and torque reference:
// one at a time. Their buttons are off while one runs, and back on when it
// ends, however it ends.
const EXPERIMENT_BUTTONS = ["step-run", "sweep-run", "capture-run"];
let experimentRunning = false;

async function experiment(outId, body) {
  if (experimentRunning) return;
  experimentRunning = true;
  for (const id of EXPERIMENT_BUTTONS) $(id).disabled = true;
  busy++;
  try {
    await body($(outId));
  } catch (e) {
    $(outId).textContent = "page error: " + e;
  } finally {
    busy--;
    experimentRunning = false;
    for (const id of EXPERIMENT_BUTTONS) $(id).disabled = false;
  }
}

$("step-run").onclick = () => experiment("step-result", async (out) => {
  out.textContent = "running";
  const arm = await cmd("capture arm step 64");
  if (!arm.ok) { out.textContent = errText(arm); return; }
  const r = await cmd("step " + $("step-nm").value.trim());
  if (!r.ok) { out.textContent = errText(r); return; }
  out.textContent = r.lines.join(", ");
  const d = await waitCapture();
  if (!d.ok) { out.textContent += " " + errText(d); return; }
  plotCapture($("step-plot"), d);
});

$("capture-run").onclick = () => experiment("capture-result", async (out) => {
  const trig = $("capture-trigger").value;
  const arm = await cmd("capture arm " + trig + " 64");
  if (!arm.ok) { out.textContent = errText(arm); return; }
  if (trig === "manual") await cmd("capture trigger");
  out.textContent = "waiting for the trigger";
  const d = await waitCapture();
  if (!d.ok) { out.textContent = errText(d); return; }
  out.textContent = (d.lines.length - 1) + " samples";
  plotCapture($("capture-plot"), d);
});

// The sweep's default range per mode, at the default amplitude of 0.3 N m
// (the amplitude of the project's bandwidth figures, README "Fig. 11"):
// each contains the torque loop's -3 dB bandwidth with room on both sides.
// Measured with `drivectl experiment sweep --amplitude 0.3 --points 16`
// on the firmware in QEMU: FOC 3355 Hz (500..3990 Hz swept), MPDTC 3930 Hz
// (1000..15000 Hz swept). FOC's range cannot reach further up: `sweep`
// refuses f_stop above a quarter of the control rate (16 kHz / 4).
// At the former 0.1 N m the FOC loop stays above -3 dB up to that limit
// (-2.7 dB at 3990 Hz), so no range would give a bandwidth, and MPDTC's
// 0.08 N m torque tolerance band is most of the sine.
const SWEEP_RANGE_HZ = { foc: [1000, 3990], mpdtc: [1000, 12000] };
// The range follows the mode until the user types one.
let sweepRangeAuto = true;
for (const id of ["sweep-f0", "sweep-f1"]) $(id).addEventListener("input", () => { sweepRangeAuto = false; });

function sweepRangeFor(mode) {
  const r = SWEEP_RANGE_HZ[mode];
  if (!r || !sweepRangeAuto) return;
  $("sweep-f0").value = r[0];
  $("sweep-f1").value = r[1];
}

// The drive reports each phase in (-180, 180] deg; the plot shows the lag
// growing past -180 deg instead of a jump of 360 deg.
function unwrapDeg(ph) {
  const out = [];
  let off = 0;
  ph.forEach((p, k) => {
    if (k > 0) {
      const d = p + off - out[k - 1];
      if (d > 180) off -= 360;
      else if (d < -180) off += 360;
    }
    out.push(p + off);
  });
  return out;
}

// Labels at 1, 2, 3 and 5 times a power of ten: a decade or less of range
// still gets labels, and a wider one no crowded 7, 8, 9.
function logTick(v) {
  if (v == null || !(v > 0)) return null;
  const m = Math.round(v / 10 ** Math.floor(Math.log10(v) + 1e-9));
  return [1, 2, 3, 5].includes(m) ? v : null;
}

$("sweep-run").onclick = () => experiment("sweep-result", async (out) => {
  out.textContent = "running";
  const line = ["sweep", $("sweep-f0").value, $("sweep-f1").value, $("sweep-amp").value, $("sweep-points").value].join(" ");
  const r = await cmd(line);
  if (!r.ok) { out.textContent = errText(r); return; }
  const f = [], g = [], ph = [];
  for (const l of r.lines) {
    const v = l.trim().split(/\s+/).map(Number);
    if (v.length === 3 && v.every(isFinite)) { f.push(v[0]); g.push(v[1]); ph.push(v[2]); }
  }
  out.textContent = r.lines.filter((l) => l.startsWith("bandwidth")).join("");
  // Log frequency axis over the swept range alone (uPlot's own range
  // would widen it to whole decades).
  const log = { time: false, distr: 3, range: (u, min, max) => [min, max] };
  const xAxis = { filter: (u, splits) => splits.map(logTick), values: (u, splits) => splits.map((v) => (v == null ? "" : String(Math.round(v)))) };
  plotInto($("sweep-gain"), { xLabel: "frequency [Hz]", xScale: log, xAxis, series: [{ label: "gain [dB]", scale: "dB" }], yAxes: [{ scale: "dB", label: "dB" }], data: [f, g] });
  plotInto($("sweep-phase"), { xLabel: "frequency [Hz]", xScale: log, xAxis, series: [{ label: "phase [deg]", scale: "deg" }], yAxes: [{ scale: "deg", label: "deg" }], data: [f, unwrapDeg(ph)] });
});

// ---- start -----------------------------------------------------------------

(async () => {
  await loadChannels();
  // The live plot runs from the start; its button stops it.
  await startTel();
  await loadConfig();
  pollTel();
  pollStatus();
  document.body.dataset.ready = "1";
})();
