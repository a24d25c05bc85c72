// The campaign page's scenario maps (loaded before app.js, whose helpers it calls when drawing):
// a top view of each scenario, its buildings as their exact footprints, and the track player.
'use strict';

function renderMaps(data) {
  const box = document.getElementById('maps');
  box.replaceChildren();
  for (const s of data.scenarios || []) {
    if (s.error) { box.append(el('p', { class: 'warn' }, `${s.file}: ${s.error}`)); continue; }
    box.append(el('div', { class: 'plot-card' }, el('h3', {}, `${s.name} (${s.venue.width} x ${s.venue.depth} m, ${s.ues.length} UEs, ${s.buildings.length} buildings)`), ...scenarioMap(s)));
  }
}

// A building from above: a footprint building as one path, its courtyards cut out (even-odd),
// a box as a rect.
function buildingShape(b, X, Y, scale, attrs) {
  if (!b.footprint) return svg('rect', { x: X(b.xmin), y: Y(b.ymax), width: (b.xmax - b.xmin) * scale, height: (b.ymax - b.ymin) * scale, ...attrs });
  const ring = r => 'M' + r.map(([x, y]) => `${X(x)},${Y(y)}`).join('L') + 'Z';
  return svg('path', { d: [b.footprint, ...(b.holes || [])].map(ring).join(''), 'fill-rule': 'evenodd', ...attrs });
}

// Where a building's label goes: a box's centre; in a footprint, the middle of the widest inside
// stretch of a few lines across it (middle first), so not in an L's notch nor in a courtyard.
function labelPoint(b) {
  const centre = [(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2];
  if (!b.footprint) return centre;
  let best = centre, widest = -1;
  for (const k of [4, 3, 5, 2, 6, 1, 7]) {
    const y = b.ymin + (b.ymax - b.ymin) * k / 8, xs = [];
    for (const r of [b.footprint, ...(b.holes || [])]) {
      r.forEach(([x0, y0], i) => {
        const [x1, y1] = r[(i + 1) % r.length];
        if ((y0 > y) !== (y1 > y)) xs.push(x0 + (y - y0) * (x1 - x0) / (y1 - y0));
      });
    }
    xs.sort((p, q) => p - q);
    for (let i = 0; i + 1 < xs.length; i += 2) {
      if (xs[i + 1] - xs[i] > widest) { widest = xs[i + 1] - xs[i]; best = [(xs[i] + xs[i + 1]) / 2, y]; }
    }
  }
  return best;
}

// A top view of the venue: buildings shaded by height, UEs, each positioner's UAV placement.
function scenarioMap(s) {
  const W = 560, H = 420, M = 30, legendW = 130;
  const scale = Math.min((W - legendW - 2 * M) / s.venue.width, (H - 2 * M) / s.venue.depth);
  const X = x => M + x * scale, Y = y => H - M - y * scale;
  const root = svg('svg', { class: 'map', viewBox: `0 0 ${W} ${H}`, 'data-scenario': s.name });
  root.append(svg('rect', { x: X(0), y: Y(s.venue.depth), width: s.venue.width * scale, height: s.venue.depth * scale, fill: '#f8fafc', stroke: '#94a3b8' }));
  for (const t of niceTicks(0, s.venue.width, 5)) root.append(svg('text', { x: X(t), y: H - M + 14, 'text-anchor': 'middle' }, fmt(t, 0)));
  for (const t of niceTicks(0, s.venue.depth, 5)) root.append(svg('text', { x: X(0) - 5, y: Y(t) + 4, 'text-anchor': 'end' }, fmt(t, 0)));
  for (const u of s.uavs) {
    const z = u.zone;
    root.append(svg('rect', { x: X(z.xmin), y: Y(z.ymax), width: (z.xmax - z.xmin) * scale, height: (z.ymax - z.ymin) * scale, fill: 'none', stroke: '#cbd5e1', 'stroke-dasharray': '4 3' }));
  }
  const tallest = Math.max(1, ...s.buildings.map(b => b.height));
  for (const b of s.buildings) {
    const shade = Math.round(200 - 120 * b.height / tallest);
    const shape = buildingShape(b, X, Y, scale, { class: 'building', fill: `rgb(${shade},${shade + 8},${shade + 20})`, stroke: '#475569' });
    const heights = b.min_height ? `${fmt(b.min_height, 1)}-${fmt(b.height, 1)} m` : `${fmt(b.height, 1)} m`;
    shape.addEventListener('mousemove', e => showTooltip(e, [{ text: b.name || 'building', bold: true }, { text: `${heights}, ${b.floors} floor(s)` }]));
    shape.addEventListener('mouseleave', hideTooltip);
    const [lx, ly] = labelPoint(b);
    root.append(shape, svg('text', { class: 'building-label', x: X(lx), y: Y(ly) + 4, 'text-anchor': 'middle' }, `${b.name || ''} ${fmt(b.height, 0)} m`));
  }
  // With track runs the UEs walk: their spec positions are where they start, drawn faint.
  const walking = !!(s.tracks && s.tracks.runs.length);
  for (const u of s.ues) {
    const dot = svg('circle', { class: walking ? 'ue ue-start' : 'ue', cx: X(u.x), cy: Y(u.y), r: walking ? 3 : 4, fill: walking ? '#94a3b8' : '#0f172a' });
    dot.addEventListener('mousemove', e => showTooltip(e, [{ text: (u.name || 'UE') + (walking ? ' at t = 0' : ''), bold: true }, { text: `(${fmt(u.x, 1)}, ${fmt(u.y, 1)}, ${fmt(u.z, 1)}) m` }, { text: `demand ${fmt(u.demand_mbps)} Mbit/s` }]));
    dot.addEventListener('mouseleave', hideTooltip);
    root.append(dot);
  }
  for (const p of s.placements) {
    const g = svg('g', { class: 'placement', 'data-positioner': p.positioner });
    if (hidden.has(p.positioner)) g.setAttribute('visibility', 'hidden');
    for (const u of p.uavs) {
      const cx = X(u.x), cy = Y(u.y);
      const marker = svg('path', { d: `M${cx},${cy - 7}L${cx + 7},${cy}L${cx},${cy + 7}L${cx - 7},${cy}Z`, fill: colorOf(p.positioner), stroke: '#fff', 'stroke-width': 1.5 });
      marker.addEventListener('mousemove', e => showTooltip(e, [{ text: `${p.positioner}: ${u.name} (run ${p.rng_run})`, bold: true, color: colorOf(p.positioner) }, { text: `(${fmt(u.x, 1)}, ${fmt(u.y, 1)}, ${fmt(u.z, 1)}) m` }]));
      marker.addEventListener('mouseleave', hideTooltip);
      g.append(marker);
    }
    root.append(g);
  }
  const names = s.placements.map(p => p.positioner);
  const player = walking ? trackPlayer(s, root, X, Y) : null;
  if (player) for (const p of s.tracks.positioners) if (!names.includes(p.positioner)) names.push(p.positioner);
  root.append(legend(names, W - legendW + 8, M));
  return player ? [root, player] : [root];
}

// --- A track run played on a map: a slider over its interval ends and play/pause; the frame
// shows the UEs where they walk then and each positioner's UAV(s) then, with the path flown so far.
// Per scenario, the run and frame shown outlive a redraw (every finished job redraws the maps).
const trackViews = new Map();

function seconds(t) { return String(+t.toFixed(2)); }

function trackPlayer(s, root, X, Y) {
  const tracks = s.tracks;
  let state = trackViews.get(s.name);
  if (!state || !tracks.runs.some(r => r.rng_run === state.run)) state = { run: tracks.runs[0].rng_run, index: 0, playing: false };
  trackViews.set(s.name, state);
  const frame = svg('g', { class: 'track-frame' });
  root.append(frame);
  const slider = el('input', { type: 'range', class: 'track-slider', min: 0, step: 1, 'data-scenario': s.name, 'aria-label': 'time' });
  const label = el('span', { class: 'track-time mono' });
  const play = el('button', { class: 'track-play', type: 'button' }, 'play');
  const runOf = () => tracks.runs.find(r => r.rng_run === state.run);
  const note = el('span', { class: 'hint' });

  function draw() {
    const run = runOf(), i = Math.min(state.index, run.times.length - 1);
    slider.max = run.times.length - 1;
    slider.value = i;
    label.textContent = `t = ${seconds(run.times[i])} s`;
    const players = tracks.positioners.filter(p => p.rng_run === run.rng_run);
    note.textContent = `RngRun ${run.rng_run}: ${players.map(p => p.positioner).join(', ')}`;
    frame.replaceChildren();
    run.ues[i].forEach(([x, y], k) => {
      const dot = svg('circle', { class: 'ue track-ue', cx: X(x), cy: Y(y), r: 4, fill: '#0f172a' });
      dot.addEventListener('mousemove', e => showTooltip(e, [{ text: `${(s.ues[k] || {}).name || 'UE'} at t = ${seconds(run.times[i])} s`, bold: true }, { text: `(${fmt(x, 1)}, ${fmt(y, 1)}) m` }]));
      dot.addEventListener('mouseleave', hideTooltip);
      frame.append(dot);
    });
    for (const p of players) {
      const g = svg('g', { class: 'track-uavs', 'data-positioner': p.positioner });
      if (hidden.has(p.positioner)) g.setAttribute('visibility', 'hidden');
      const color = colorOf(p.positioner);
      p.uavs[i].forEach(([x, y, z], u) => {
        const flown = p.uavs.slice(0, i + 1).map(f => `${X(f[u][0])},${Y(f[u][1])}`).join(' ');
        g.append(svg('polyline', { class: 'track-path', points: flown, stroke: color }));
        const cx = X(x), cy = Y(y);
        const marker = svg('path', { class: 'track-uav', d: `M${cx},${cy - 7}L${cx + 7},${cy}L${cx},${cy + 7}L${cx - 7},${cy}Z`, fill: color, stroke: '#fff', 'stroke-width': 1.5 });
        marker.addEventListener('mousemove', e => showTooltip(e, [{ text: `${p.positioner}: ${(s.uavs[u] || {}).name || 'UAV'} at t = ${seconds(run.times[i])} s (run ${run.rng_run})`, bold: true, color }, { text: `(${fmt(x, 1)}, ${fmt(y, 1)}, ${fmt(z, 1)}) m` }]));
        marker.addEventListener('mouseleave', hideTooltip);
        g.append(marker);
      });
      frame.append(g);
    }
  }

  let timer = null;
  function halt() { clearInterval(timer); timer = null; play.textContent = 'play'; }
  const last = () => runOf().times.length - 1;
  function start() {
    if (state.index >= last()) state.index = 0;
    state.playing = true;
    play.textContent = 'pause';
    // A whole run in about 20 s, whatever its number of intervals.
    timer = setInterval(() => {
      if (!root.isConnected) { halt(); return; }  // redrawn: the new map plays on
      state.index = Math.min(state.index + 1, last());
      draw();
      if (state.index >= last()) { state.playing = false; halt(); }
    }, Math.min(500, Math.max(40, 20000 / (last() + 1))));
  }
  play.addEventListener('click', () => { if (timer) { state.playing = false; halt(); } else start(); });
  slider.addEventListener('input', () => { state.index = Number(slider.value); draw(); });
  const controls = el('div', { class: 'track-controls', 'data-scenario': s.name }, play, slider, label);
  if (tracks.runs.length > 1) {
    const select = el('select', { class: 'track-run' }, ...tracks.runs.map(r => el('option', { value: r.rng_run }, `RngRun ${r.rng_run}`)));
    select.value = state.run;
    select.addEventListener('change', () => { state.run = Number(select.value); state.index = 0; draw(); });
    controls.append(select);
  }
  controls.append(note);
  draw();
  if (state.playing) start();
  return controls;
}
