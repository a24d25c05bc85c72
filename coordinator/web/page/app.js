// The campaign page: reads /api/ only, draws everything in SVG, no library, works offline.
'use strict';

const POLL_MS = 2000;
const SVG_NS = 'http://www.w3.org/2000/svg';
const STATES = ['succeeded', 'failed', 'running', 'ready', 'pending', 'cancelled'];

// --- Access: a token given once in the page's URL is kept for this tab and sent as a header.
(function keepToken() {
  const params = new URLSearchParams(location.search);
  if (params.has('token')) {
    sessionStorage.setItem('rlpos-token', params.get('token'));
    history.replaceState(null, '', location.pathname + location.hash);
  }
})();

function authHeaders() {
  const token = sessionStorage.getItem('rlpos-token');
  return token ? { Authorization: 'Bearer ' + token } : {};
}

async function api(path) {
  const response = await fetch(path, { headers: authHeaders(), cache: 'no-store' });
  if (!response.ok) {
    let message = response.status + ' ' + response.statusText;
    try { message = (await response.json()).error || message; } catch (e) { /* not JSON */ }
    throw new Error(message);
  }
  return response.json();
}

// --- Small helpers
function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'class') node.className = v;
    else if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else node.setAttribute(k, v);
  }
  for (const c of children) node.append(c instanceof Node ? c : document.createTextNode(c));
  return node;
}

function svg(tag, attrs, ...children) {
  const node = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  for (const c of children) node.append(c instanceof Node ? c : document.createTextNode(c));
  return node;
}

function fmt(value, digits) {
  if (value === null || value === undefined || Number.isNaN(value)) return '-';
  if (typeof value !== 'number') return String(value);
  if (digits === undefined) digits = Math.abs(value) >= 100 ? 1 : Math.abs(value) >= 1 ? 2 : 3;
  return value.toFixed(digits);
}

function duration(seconds) {
  if (seconds === null || seconds === undefined) return '-';
  seconds = Math.max(0, Math.round(seconds));
  const h = Math.floor(seconds / 3600), m = Math.floor((seconds % 3600) / 60), s = seconds % 60;
  if (h) return h + 'h' + String(m).padStart(2, '0') + 'm';
  if (m) return m + 'm' + String(s).padStart(2, '0') + 's';
  return s + 's';
}

// Positioner colours: the same in every plot and map of the page.
const BASE_COLORS = {
  baseline: '#6b7280', centroid: '#f59e0b', oracle: '#16a34a', rl: '#dc2626',
  offset1: '#93c5fd', offset2: '#60a5fa', offset3: '#3b82f6', offset4: '#2563eb', offset5: '#1d4ed8',
};
const EXTRA_COLORS = ['#9333ea', '#db2777', '#0891b2', '#65a30d', '#c2410c', '#4f46e5', '#0d9488', '#a16207'];
const assigned = {};
function colorOf(label) {
  if (BASE_COLORS[label]) return BASE_COLORS[label];
  if (!assigned[label]) assigned[label] = EXTRA_COLORS[Object.keys(assigned).length % EXTRA_COLORS.length];
  return assigned[label];
}

// Positioners hidden by a click on a legend entry, for every plot and map of the campaign.
const hidden = new Set();

// --- Axis ticks
function niceTicks(min, max, count) {
  if (!(max > min)) { max = min + 1; }
  const span = max - min, raw = span / count, mag = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 2.5, 5, 10].map(f => f * mag).find(s => span / s <= count) || 10 * mag;
  const ticks = [];
  for (let t = Math.ceil(min / step) * step; t <= max + step * 1e-9; t += step) ticks.push(+t.toFixed(10));
  ticks.digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9)) + (String(step).includes('.25') ? 1 : 0);
  return ticks;
}

function extent(values) {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) { if (v < lo) lo = v; if (v > hi) hi = v; }
  if (lo === Infinity) return [0, 1];
  if (lo === hi) { lo -= Math.abs(lo) * 0.05 || 0.5; hi += Math.abs(hi) * 0.05 || 0.5; }
  return [lo, hi];
}

// --- A line plot with axes, legend (click toggles), and a hover read-out.
// series: [{name, color, x: [], y: [], step: 'ccdf'|'cdf'|null}]
function linePlot(options) {
  // Room on the right for the longest legend entry (11 px text, about 6.2 px a character):
  // "rl+generalist-multi, 6 UAVs" would otherwise run off the plot's edge.
  const longest = Math.max(0, ...options.series.map(s => s.name.length));
  const W = 560, H = 300, M = { l: 52, r: Math.max(130, 32 + Math.ceil(6.2 * longest)), t: 10, b: 40 };
  const pw = W - M.l - M.r, ph = H - M.t - M.b;
  const root = svg('svg', { class: 'plot', viewBox: `0 0 ${W} ${H}`, 'data-kind': options.kind || '' });
  const all = options.series;
  const [xa, xb] = extent(all.flatMap(s => s.x));
  const pad = (xb - xa) * 0.04, x0 = xa - pad, x1 = xb + pad;
  const [y0, y1] = options.yDomain || extent(all.flatMap(s => s.y));
  const X = v => M.l + (v - x0) / (x1 - x0) * pw;
  const Y = v => M.t + ph - (v - y0) / (y1 - y0) * ph;
  const grid = svg('g', { class: 'grid' }), axis = svg('g', { class: 'axis' });
  const xt = niceTicks(x0, x1, 6), yt = niceTicks(y0, y1, 5);
  for (const t of xt) {
    grid.append(svg('line', { x1: X(t), x2: X(t), y1: M.t, y2: M.t + ph }));
    axis.append(svg('text', { x: X(t), y: M.t + ph + 15, 'text-anchor': 'middle' }, fmt(t, xt.digits)));
  }
  for (const t of yt) {
    grid.append(svg('line', { x1: M.l, x2: M.l + pw, y1: Y(t), y2: Y(t) }));
    axis.append(svg('text', { x: M.l - 6, y: Y(t) + 4, 'text-anchor': 'end' }, fmt(t, yt.digits)));
  }
  axis.append(svg('path', { d: `M${M.l},${M.t}V${M.t + ph}H${M.l + pw}`, fill: 'none' }));
  axis.append(svg('text', { x: M.l + pw / 2, y: H - 6, 'text-anchor': 'middle' }, options.xLabel));
  axis.append(svg('text', { x: 12, y: M.t + ph / 2, transform: `rotate(-90 12 ${M.t + ph / 2})`, 'text-anchor': 'middle' }, options.yLabel));
  root.append(grid, axis);
  const lines = svg('g', {});
  for (const s of all) {
    let d = '';
    if (s.step) {
      const start = s.step === 'ccdf' ? 1 : 0;
      d = `M${X(s.x[0])},${Y(start)}`;
      for (let i = 0; i < s.x.length; i++) {
        d += `V${Y(s.y[i])}`;
        if (i + 1 < s.x.length) d += `H${X(s.x[i + 1])}`;
      }
    } else {
      d = s.x.map((x, i) => (i ? 'L' : 'M') + X(x) + ',' + Y(s.y[i])).join('');
    }
    const path = svg('path', { class: 'series', d, stroke: s.color, 'data-positioner': s.name });
    if (hidden.has(s.name)) path.setAttribute('visibility', 'hidden');
    lines.append(path);
  }
  root.append(lines);
  root.append(legend(all.map(s => s.name), W - M.r + 12, M.t + 4));
  const guide = svg('line', { class: 'guide', y1: M.t, y2: M.t + ph, visibility: 'hidden' });
  root.append(guide);
  const overlay = svg('rect', { x: M.l, y: M.t, width: pw, height: ph, fill: 'transparent' });
  overlay.addEventListener('mousemove', event => {
    const box = root.getBoundingClientRect();
    const px = (event.clientX - box.left) * W / box.width;
    const xv = x0 + (px - M.l) / pw * (x1 - x0);
    guide.setAttribute('x1', px); guide.setAttribute('x2', px); guide.setAttribute('visibility', 'visible');
    showTooltip(event, [{ text: `${options.xLabel}: ${fmt(xv)}`, bold: true }].concat(all.filter(s => !hidden.has(s.name))
      .map(s => ({ text: `${s.name}: ${fmt(valueAt(s, xv))}`, color: s.color }))));
  });
  overlay.addEventListener('mouseleave', () => { guide.setAttribute('visibility', 'hidden'); hideTooltip(); });
  root.append(overlay);
  return root;
}

// The series' value at x: the step function's, or the nearest point's.
function valueAt(s, x) {
  if (s.step) {
    let v = s.step === 'ccdf' ? 1 : 0;
    for (let i = 0; i < s.x.length && s.x[i] <= x; i++) v = s.y[i];
    return v;
  }
  let best = 0;
  for (let i = 1; i < s.x.length; i++) if (Math.abs(s.x[i] - x) < Math.abs(s.x[best] - x)) best = i;
  return s.y[best];
}

function legend(names, x, y) {
  const g = svg('g', { class: 'legend' });
  names.forEach((name, i) => {
    const item = svg('g', { class: 'legend-item' + (hidden.has(name) ? ' off' : ''), transform: `translate(${x},${y + i * 17})`, 'data-positioner': name });
    item.append(svg('rect', { width: 12, height: 12, rx: 2, fill: colorOf(name) }), svg('text', { x: 17, y: 10 }, name));
    item.addEventListener('click', () => toggle(name));
    g.append(item);
  });
  return g;
}

function toggle(name) {
  if (hidden.has(name)) hidden.delete(name); else hidden.add(name);
  for (const node of document.querySelectorAll(`[data-positioner="${CSS.escape(name)}"]`)) {
    if (node.classList.contains('legend-item')) node.classList.toggle('off', hidden.has(name));
    else node.setAttribute('visibility', hidden.has(name) ? 'hidden' : 'visible');
  }
}

const tooltip = document.getElementById('tooltip');
// lines: [{text, bold, color}]; built as nodes (the page's CSP admits no inline style attribute).
function showTooltip(event, lines) {
  tooltip.replaceChildren();
  lines.forEach((line, i) => {
    if (i) tooltip.append(el('br'));
    if (line.color) { const sw = el('i'); sw.style.background = line.color; tooltip.append(sw); }
    tooltip.append(line.bold ? el('b', {}, line.text) : document.createTextNode(line.text));
  });
  tooltip.hidden = false;
  const left = Math.min(event.clientX + 14, window.innerWidth - tooltip.offsetWidth - 8);
  tooltip.style.left = left + 'px';
  tooltip.style.top = (event.clientY + 14) + 'px';
}
function hideTooltip() { tooltip.hidden = true; }

// --- The campaign list
function progressCell(c) {
  const track = el('div', { class: 'track' });
  for (const state of STATES) {
    const n = c.jobs[state];
    if (n) track.append(el('span', { class: 'seg-' + state, title: `${n} ${state}` }));
    if (n) track.lastChild.style.width = (100 * n / Math.max(1, c.total)) + '%';
  }
  return el('div', { class: 'progress' }, track,
    el('span', { class: 'progress-text mono', 'data-done': c.done, 'data-total': c.total }, `${c.done}/${c.total}`));
}

function renderList(data) {
  const body = document.querySelector('#campaign-list tbody');
  body.replaceChildren();
  for (const c of data.campaigns) {
    const row = el('tr', { class: 'campaign', 'data-id': c.id, onclick: () => { location.hash = '#/campaign/' + c.id; } },
      el('td', {}, c.name), el('td', { class: 'mono' }, c.id),
      el('td', {}, el('span', { class: 'badge ' + c.state }, c.state)),
      el('td', {}, progressCell(c)),
      el('td', { class: 'num' }, String(c.jobs.failed)),
      el('td', { class: 'num' }, c.settled ? 'done' : duration(c.eta_s)));
    body.append(row);
  }
  document.getElementById('list-empty').hidden = data.campaigns.length > 0;
}

// --- One campaign
function card(label, value, cls) {
  return el('div', { class: 'card' }, el('div', { class: 'label' }, label), el('div', { class: 'value ' + (cls || '') }, value));
}

function renderCampaign(c) {
  document.getElementById('campaign-title').replaceChildren(c.name, el('small', { class: 'mono' }, c.id),
    el('small', {}, el('span', { class: 'badge ' + c.state }, c.state)));
  const elapsed = c.first_started_at ? (c.settled ? (c.last_finished_at || c.now) : c.now) - c.first_started_at : null;
  document.getElementById('campaign-cards').replaceChildren(
    card('Done', el('span', { id: 'campaign-done', 'data-done': c.done, 'data-total': c.total }, `${c.done} / ${c.total}`)),
    card('Running', String(c.jobs.running)), card('Failed', String(c.jobs.failed), c.jobs.failed ? 'bad' : ''),
    card('From cache', String(c.jobs.cached)),
    card('Workers alive', `${c.workers.alive}`),
    card(c.settled ? 'Ran for' : 'ETA', c.settled ? duration(elapsed) : duration(c.eta_s)));
  const bar = document.getElementById('campaign-bar');
  bar.replaceChildren();
  const states = el('div', { class: 'legend-states' });
  for (const state of STATES) {
    const n = c.jobs[state];
    if (n) { const s = el('span', { class: 'seg-' + state, title: `${n} ${state}` }); s.style.width = (100 * n / Math.max(1, c.total)) + '%'; bar.append(s); }
    states.append(el('span', {}, el('i', { class: 'seg-' + state }), `${state} ${n}`));
  }
  const jobs = document.getElementById('campaign-jobs');
  jobs.replaceChildren(states);
  if (c.failed.length) {
    jobs.append(el('h2', {}, `Failed jobs (${c.failed_total})`), table(['job', 'attempts', 'error'],
      c.failed.map(f => [el('span', { class: 'mono' }, f.key), String(f.attempts), el('span', { class: 'failed-error' }, f.error)])));
  }
  if (c.running.length) {
    jobs.append(el('h2', {}, `Running (${c.running_total})`), table(['job', 'worker', 'attempt', 'for', 'progress'],
      c.running.map(r => [el('span', { class: 'mono' }, r.key), r.worker, String(r.attempt), duration(c.now - r.started_at), r.progress])));
  }
  renderTables(c);
  renderArtifacts(c);
}

function table(headers, rows, numeric) {
  const t = el('table', { class: 'grid' });
  t.append(el('thead', {}, el('tr', {}, ...headers.map(h => el('th', {}, h)))));
  const body = el('tbody');
  for (const r of rows) body.append(el('tr', {}, ...r.map((v, i) => el('td', { class: numeric && numeric[i] ? 'num' : '' }, v))));
  t.append(body);
  return t;
}

const SUMMARY_COLUMNS = [
  ['scenario', 'scenario'], ['positioner', 'positioner'], ['runs', 'runs'],
  ['throughput_median_mbps', 'median Mbit/s'], ['throughput_mean_mbps', 'mean Mbit/s'],
  ['throughput_ci95_mbps', '\u00b1 CI95'], ['throughput_change_pct', '\u0394 vs baseline %'],
  ['delay_mean_ms', 'delay ms'], ['delay_change_pct', '\u0394 delay %'], ['nlos_ratio_mean', 'LoS share'],
  ['demands_met_mean', 'demands met'], ['worst_ue_mean_mbps', 'worst UE Mbit/s'], ['jain_mean', 'Jain'],
];

// Real numbers that may happen to be whole (a ratio of 1), shown with 3 decimals.
const RATIO_COLUMNS = { ratio: 1, rl_reward: 1, oracle_reward: 1, median: 1, p10: 1, worst: 1,
  near_optimal_share: 1 };

function objectTable(rows, columns) {
  const keys = columns || Object.keys(rows[0] || {}).map(k => [k, k.replace(/_/g, ' ')]);
  return table(keys.map(k => k[1]), rows.map(r => keys.map(([k]) => {
    const v = r[k];
    if (k === 'positioner' || k === 'label') {
      const sw = el('span', {}, el('i', { class: 'swatch' }), String(v));
      sw.firstChild.style.cssText = `display:inline-block;width:9px;height:9px;border-radius:2px;margin-right:5px;background:${colorOf(v)}`;
      return sw;
    }
    if (typeof v === 'number') {
      if (k in RATIO_COLUMNS) return fmt(v, 3);  // 1 reads as 1.000, like its neighbours
      return Number.isInteger(v) ? String(v) : fmt(v);
    }
    return v === null ? '-' : String(v);
  })), keys.map(([k]) => typeof (rows[0] || {})[k] === 'number'));
}

function renderTables(c) {
  const summary = document.getElementById('summary-table');
  summary.replaceChildren(c.summary.length ? objectTable(c.summary, SUMMARY_COLUMNS.filter(([k]) => k in c.summary[0]))
    : el('p', { class: 'empty' }, 'No eval result yet.'));
  const optimality = c.optimality;
  document.getElementById('optimality-section').hidden = !optimality.summary.length;
  document.getElementById('optimality-table').replaceChildren(optimality.summary.length ? objectTable(optimality.summary, [
    ['algorithm', 'algorithm'], ['uavs', 'UAVs'], ['runs', 'runs'], ['median', 'median'], ['p10', 'P10'],
    ['worst', 'worst'], ['near_optimal_share', 'share >= 0.95'], ['median_placement_s', 'placement s']]) : '');
  document.getElementById('optimality-plot').replaceChildren(...optimalityPlot(optimality.cdf));
  document.getElementById('optimality-runs').replaceChildren(optimality.runs.length ? objectTable(optimality.runs, [
    ['scenario', 'scenario'], ['uavs', 'UAVs'], ['algorithm', 'algorithm'], ['train_seed', 'train seed'],
    ['rl_reward', 'reward'], ['oracle_reward', 'oracle reward'], ['ratio', 'ratio'], ['placement_s', 'placement s']]) : '');
  document.getElementById('per-uav-section').hidden = !c.per_uav.length;
  document.getElementById('per-uav-table').replaceChildren(c.per_uav.length ? objectTable(c.per_uav) : '');
}

async function download(artifact) {
  const response = await fetch(artifact.url, { headers: authHeaders() });
  if (!response.ok) { alert('Download failed: ' + response.status); return; }
  const url = URL.createObjectURL(await response.blob());
  const a = el('a', { href: url, download: artifact.name });
  document.body.append(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

function renderArtifacts(c) {
  const box = document.getElementById('artifacts');
  if (!c.artifacts.length) { box.replaceChildren(el('p', { class: 'empty' }, 'No artifact.')); return; }
  box.replaceChildren(table(['job', 'name', 'size', 'sha256', ''], c.artifacts.map(a => [
    el('span', { class: 'mono' }, a.job), a.name, (a.bytes / 1024).toFixed(1) + ' KiB',
    el('span', { class: 'mono' }, a.sha256.slice(0, 12)),
    el('button', { class: 'link artifact-download', 'data-artifact': a.id, onclick: () => download(a) }, 'download')])));
  if (c.artifacts_total > c.artifacts.length) box.append(el('p', { class: 'hint' }, `first ${c.artifacts.length} of ${c.artifacts_total}`));
}

// --- Plots
// The ratio's CDF, one curve per algorithm (named policy, positioner) and UAV count: per-scenario
// training and a policy for any scenario side by side.
function optimalityPlot(curves) {
  if (!curves.length) return [];
  // With one UAV count, a curve is named (and coloured) as its positioner is everywhere else.
  const single = new Set(curves.map(c => c.uavs)).size === 1;
  const name = c => single ? (c.algorithm || '-') : `${c.algorithm || '-'}, ${c.uavs} UAV${c.uavs === 1 ? '' : 's'}`;
  const plot = linePlot({
    kind: 'cdf', xLabel: 'reward / oracle reward', yLabel: 'P(ratio \u2264 x)', yDomain: [0, 1],
    series: curves.map(c => ({ name: name(c), color: colorOf(name(c)), x: c.x, y: c.p, step: 'cdf' })),
  });
  plot.setAttribute('data-plot', 'optimality');
  return [el('div', { class: 'plot-card' }, el('h3', {}, 'CDF of each placement\u2019s reward over the oracle\u2019s'), plot)];
}

function renderDistributions(data) {
  const box = document.getElementById('distribution-plots');
  box.replaceChildren();
  const byScenario = new Map();
  for (const curve of data.curves) {
    if (!byScenario.has(curve.scenario)) byScenario.set(curve.scenario, []);
    byScenario.get(curve.scenario).push(curve);
  }
  if (!byScenario.size) box.append(el('p', { class: 'empty' }, 'No eval result yet.'));
  const what = data.kind === 'ccdf' ? `P(${data.name} > x)` : `P(${data.name} \u2264 x)`;
  for (const [scenario, curves] of byScenario) {
    const plot = linePlot({
      kind: data.kind, xLabel: `${data.name} (${data.unit})`, yLabel: what, yDomain: [0, 1],
      series: curves.map(c => ({ name: c.positioner, color: colorOf(c.positioner), x: c.x, y: c.p, step: data.kind })),
    });
    plot.setAttribute('data-scenario', scenario);
    plot.setAttribute('data-metric', data.metric);
    box.append(el('div', { class: 'plot-card' }, el('h3', {}, `${scenario}: ${data.kind.toUpperCase()} of ${data.name}`), plot));
  }
}

function renderLearning(data) {
  const box = document.getElementById('learning-plots');
  box.replaceChildren();
  const byScenario = new Map();
  for (const curve of data.curves) {
    if (!byScenario.has(curve.scenario)) byScenario.set(curve.scenario, []);
    byScenario.get(curve.scenario).push(curve);
  }
  if (!byScenario.size) box.append(el('p', { class: 'empty' }, 'No learning curve (no rl training in this campaign, or none finished yet).'));
  for (const [scenario, curves] of byScenario) {
    const plot = linePlot({
      kind: 'learning', xLabel: 'episode', yLabel: 'total reward',
      series: curves.map(c => ({ name: c.label, color: colorOf(c.label), x: c.episode, y: c.reward })),
    });
    plot.setAttribute('data-scenario', scenario);
    box.append(el('div', { class: 'plot-card' }, el('h3', {}, `${scenario}: training reward per episode`), plot));
  }
  if (data.skipped) box.append(el('p', { class: 'warn' }, `${data.skipped} curve file(s) could not be read.`));
}

// --- The scenario maps and their track player: map.js.

// --- State and polling
const view = { id: null, metric: 'aggregate_throughput_mbps', plottedDone: -1, metrics: [] };

function fillMetricSelect(metrics) {
  const select = document.getElementById('metric-select');
  if (select.options.length) return;
  for (const m of metrics) select.append(el('option', { value: m.metric }, `${m.name} (${m.unit}, ${m.kind.toUpperCase()})`));
  select.value = view.metric;
  select.addEventListener('change', () => { view.metric = select.value; view.plottedDone = -1; refresh(); });
}

async function refreshPlots(c) {
  const base = '/api/campaigns/' + c.id;
  const [dist, learning, maps] = await Promise.all([
    api(base + '/distributions?metric=' + encodeURIComponent(view.metric)),
    api(base + '/learning-curves'), api(base + '/maps')]);
  if (view.id !== c.id) return;
  renderDistributions(dist);
  renderLearning(learning);
  renderMaps(maps);
  document.body.setAttribute('data-plotted-done', String(c.done));
  // For the benchmark: when the campaign view was first drawn whole, since navigation start.
  if (!performance.getEntriesByName('rlpos-plotted').length) performance.mark('rlpos-plotted');
}

async function refresh() {
  const connection = document.getElementById('connection');
  try {
    if (view.id) {
      const c = await api('/api/campaigns/' + view.id);
      fillMetricSelect(c.metrics);
      renderCampaign(c);
      // Plots change only when jobs finish: redrawn then, not on every poll.
      if (c.done !== view.plottedDone) { view.plottedDone = c.done; await refreshPlots(c); }
    } else {
      renderList(await api('/api/campaigns'));
    }
    connection.textContent = 'live, updated ' + new Date().toLocaleTimeString();
    connection.className = 'connection live';
  } catch (error) {
    connection.textContent = 'not updated: ' + error.message;
    connection.className = 'connection down';
  }
}

function route() {
  const match = location.hash.match(/^#\/campaign\/([0-9a-f]{12})$/);
  view.id = match ? match[1] : null;
  view.plottedDone = -1;
  hidden.clear();
  trackViews.clear();
  document.getElementById('list-view').hidden = !!view.id;
  document.getElementById('campaign-view').hidden = !view.id;
  refresh();
}

let polling = false;
async function poll() {
  if (!polling) { polling = true; try { await refresh(); } finally { polling = false; } }
}

window.addEventListener('hashchange', route);
route();
setInterval(poll, POLL_MS);
