// raylab-web's page: the editor, the live picture and the check, over two
// Workers running raylab's C++ (web/worker.js). Everything is in this one
// file: it opens from file:// with no network.
'use strict';

const WORKER_SOURCE = atob(RAYLAB_MODULE_B64) + '\n' + /*@WORKER_JS@*/'';
const workerUrl = URL.createObjectURL(new Blob([WORKER_SOURCE], {type: 'text/javascript'}));
// As `raylab check --timeout`: seconds allowed per exercise (native default 60).
const CHECK_TIMEOUT_SECONDS = 60;
const STORAGE_PREFIX = 'raylab:exercises/';

// ---- a Worker with request/response calls ------------------------------------------------------
class RaylabWorker {
  constructor() {
    this.worker = new Worker(workerUrl);
    this.next = 1;
    this.pending = new Map();
    this.worker.onmessage = (event) => {
      const msg = event.data;
      const p = this.pending.get(msg.id);
      if (!p) return;
      if (!msg.done) { if (p.progress) p.progress(msg); return; }
      this.pending.delete(msg.id);
      if (msg.ok) p.resolve(msg); else p.reject(new Error(msg.error));
    };
    this.worker.onerror = (event) => {
      for (const p of this.pending.values()) p.reject(new Error(event.message || 'the worker failed'));
      this.pending.clear();
    };
  }
  call(op, args = {}, progress = null, transfer = []) {
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, {resolve, reject, progress});
      this.worker.postMessage(Object.assign({id, op}, args), transfer);
    });
  }
  terminate() {
    this.worker.terminate();
    for (const p of this.pending.values()) p.reject(new Error('terminated'));
    this.pending.clear();
  }
}

// ---- state ----------------------------------------------------------------------------------
const state = {exercises: [], stubs: {}, files: {}, current: null, editor: null, context: '',
               verdicts: {}};  // file -> Map(text -> the status a check gave that text)
let checker = null;   // the check Worker (replaced after a timeout)
let painter = null;   // the live picture's Worker
const $ = (id) => document.getElementById(id);
const setStatus = (text) => { $('status').textContent = text; };

// ---- the page's words for the native program's ----------------------------------------------
// A handout's path (docs/exercises/05-ggx.md, course/05-ggx/handout.md).
const HANDOUT_PATH = /\b(?:docs\/exercises\/(\d\d-[a-z-]+)\.md|course\/(\d\d-[a-z-]+)\/handout\.md)\b/g;
// The stub as the page shows it: its comments speak of the page (the
// handout beside the editor, the Check button), not of command lines. Same
// lines, so that line numbers in messages are the editor's.
function pageStub(name) {
  return state.stubs[name].split('\n').map((line) => {
    const comment = line.indexOf('//');
    if (comment < 0) return line;
    let text = line.slice(comment);
    text = text.replace(/Handout: \S+\.md/, 'Handout: beside this editor');
    text = text.replace(/(?:\S*\/)?raylab check(?: --exercise \d+)?/, 'the "Check this exercise" button');
    return line.slice(0, comment) + text;
  }).join('\n');
}
// What the checker, the picture and the download get: the page's stub is
// the shipped stub (so an untouched file is NOT STARTED as "the unchanged
// stub", natively and by raylab grade).
function repositoryText(name, text) {
  return text === pageStub(name) ? state.stubs[name] : text;
}
function repositoryFiles() {
  const out = {};
  for (const [name, text] of Object.entries(state.files)) out[name] = repositoryText(name, text);
  return out;
}
// A check's text as the page shows it: the handouts are beside the editor,
// the pictures below (there is no check-output/ folder in a browser).
function pageReportText(text) {
  return text
      .replace(/the handout: /g, 'the handout ')
      .replace(HANDOUT_PATH, (all, a, b) => '"' + (a || b) + '" (the handout beside the editor)')
      .replace(/raylab render compiles the ten files/g, 'the picture beside the editor compiles the ten files')
      .replace(/^(\s+)expected +check-output\/\S+\n(?:\s+got +check-output\/\S+\n)?(?:\s+diff +check-output\/\S+\n)?/gm,
               '$1expected, got and difference: the pictures below\n')
      .replace(/check-output\/\S*/g, 'the pictures below');
}

function load(name) {
  let text = state.stubs[name];
  try {
    const saved = localStorage.getItem(STORAGE_PREFIX + name);
    if (saved !== null) text = saved;
  } catch (e) { /* storage refused (private mode): the stub */ }
  return text === state.stubs[name] ? pageStub(name) : text;
}
function save(name, text) {
  state.files[name] = text;
  try {
    localStorage.setItem(STORAGE_PREFIX + name, text);
    $('saved').textContent = 'saved in this browser';
  } catch (e) {
    $('saved').textContent = 'NOT saved: this browser refuses storage; download your files';
  }
}

// ---- editor ---------------------------------------------------------------------------------
function showFile(name) {
  state.current = name;
  state.editor.setValue(state.files[name]);
  state.editor.clearHistory();
  for (const b of $('tabs').children) b.classList.toggle('active', b.dataset.file === name);
  showHandout(state.exercises.find((e) => e.file === name));
}
// The exercise's handout beside the editor (rendered at build time, web/handouts.js).
function showHandout(exercise) {
  const handout = (typeof RAYLAB_HANDOUTS !== 'undefined' ? RAYLAB_HANDOUTS : {})[exercise.id];
  $('handout-title').textContent = handout ? 'Handout: ' + handout.title : 'No handout for ' + exercise.file;
  $('handout-title').title = handout ? handout.path + ' in the raylab repository' : '';
  $('handout').innerHTML = handout ? handout.html : '';
  $('handout').dataset.exercise = exercise.id;
  $('handout-pane').scrollTop = 0;
  // The handout's command lines that the page has as buttons get one beside them.
  for (const code of $('handout').querySelectorAll('code')) {
    const text = code.textContent.trim();
    const checkCommand = text.match(/^\.\/raylab check --exercise (\d+)$/);
    const view = text.match(/^\.\/raylab render .*--view (\w+)/);
    const option = view && [...$('view').options].find((o) => o.value === view[1]);
    if (!checkCommand && !option) continue;
    const button = document.createElement('button');
    button.className = 'in-page';
    if (checkCommand) {
      button.textContent = 'Check this exercise';
      button.title = 'In this page: what ' + text + ' does';
      button.onclick = () => runCheckOf(Number(checkCommand[1]));
    } else {
      button.textContent = 'Show the ' + option.textContent + ' view';
      button.title = 'In this page: the View menu beside the picture';
      button.onclick = () => { $('view').value = option.value; drawLive(); };
    }
    const where = code.parentElement.tagName === 'PRE' ? code.parentElement : code;
    where.insertAdjacentElement('afterend', button);
  }
}
function runCheckOf(number) {
  const exercise = state.exercises.find((e) => e.number === number);
  if (exercise && exercise.file !== state.current) showFile(exercise.file);
  return check([number]);
}
function wireHandout() {
  $('toggle-handout').onclick = () => document.body.classList.toggle('no-handout');
  $('handout').addEventListener('click', (event) => {
    const link = event.target.closest('a');
    if (!link) return;
    if (link.dataset.handout) {  // another exercise's handout: its tab
      event.preventDefault();
      const exercise = state.exercises.find((e) => e.id === link.dataset.handout);
      if (exercise) showFile(exercise.file);
    } else if (link.classList.contains('repo-link')) {
      event.preventDefault();  // a file of the repository, not in the page (its path is the title)
    }
  });
}
function buildTabs() {
  for (const e of state.exercises) {
    const b = document.createElement('button');
    b.dataset.file = e.file;
    b.title = e.title + ' (its handout opens beside the editor)';
    b.innerHTML = '<span></span><span class="mark"></span>';
    b.firstChild.textContent = e.file;
    b.onclick = () => showFile(e.file);
    $('tabs').appendChild(b);
  }
}
// A tab's mark is the verdict of the file as it is now: the last check of
// this very text, or none (a dot) when the text has not been checked. A file
// put back to a text that passed is ✓ again, one put back to the stub loses
// its mark.
function recordVerdict(file, text, status) {
  if (!state.verdicts[file]) state.verdicts[file] = new Map();
  const known = state.verdicts[file];
  known.delete(text);
  known.set(text, status);
  if (known.size > 50) known.delete(known.keys().next().value);  // the oldest
}
function markTab(file) {
  const text = state.files[file];
  const known = state.verdicts[file];
  let status = known && known.has(text) ? known.get(text) : null;
  if (status === null && repositoryText(file, text) === state.stubs[file]) status = 'NOT STARTED';
  for (const b of $('tabs').children)
    if (b.dataset.file === file) {
      const mark = b.lastChild;
      mark.textContent = status === null ? '•' : status === 'PASS' ? '✓' : status === 'NOT STARTED' ? '' : '✗';
      mark.className = 'mark ' + (status === null ? 'changed' : status);
      mark.title = status === null ? 'changed since the last check' : status;
      b.dataset.status = status === null ? 'changed' : status;
    }
}
function markAllTabs() { for (const e of state.exercises) markTab(e.file); }

// ---- check ----------------------------------------------------------------------------------
function timeoutReport(exercise) {
  // The native checker's words for a check that does not end (app/checks/checker.cpp).
  const r = {exercise: exercise.id, number: exercise.number, status: 'TIMEOUT',
    message: 'the check timed out after ' + CHECK_TIMEOUT_SECONDS + ' s: does a loop in ' + exercise.file + ' never end?',
    hint: 'every loop needs a bound; the trace loop runs at most maxBounces() + 1 times', details: '', probes: [], images: []};
  r.text = (r.exercise.padEnd(17) + ' ' + r.status.padEnd(13) + ' ' + r.message + '\n    hint: ' + r.hint + '\n');
  return r;
}

function withTimeout(promise, seconds) {
  let timer;
  const limit = new Promise((resolve) => { timer = setTimeout(() => resolve('timeout'), seconds * 1000); });
  return Promise.race([promise, limit]).finally(() => clearTimeout(timer));
}

function showImages(images) {
  for (const [path, bytes] of Object.entries(images || {})) {
    const fig = document.createElement('figure');
    const img = document.createElement('img');
    img.src = URL.createObjectURL(new Blob([bytes], {type: 'image/png'}));
    // check-output/05-ggx/metal-row-diff.png: "metal-row: diff" (no such folder in a browser)
    const caption = path.replace(/^.*\//, '').replace(/\.png$/, '').replace(/-(expected|got|diff)$/, ': $1');
    img.alt = caption;
    img.dataset.path = path;
    fig.appendChild(img);
    fig.appendChild(document.createTextNode(caption));
    $('check-images').appendChild(fig);
  }
}

// Checks the given exercises (numbers) as `raylab check --exercise N...` does,
// then the ten files together. Returns {reports, together, text}.
async function check(numbers) {
  numbers = numbers || state.exercises.map((e) => e.number);
  const started = performance.now();
  $('check-text').textContent = '';
  $('check-images').textContent = '';
  const reports = [];
  for (const number of numbers) {
    const exercise = state.exercises.find((e) => e.number === number);
    setStatus('checking ' + exercise.file + '…');
    const sent = repositoryFiles();
    const checked = state.files[exercise.file];  // the text this verdict is for (the editor may change meanwhile)
    const call = checker.call('check', {files: sent, exercises: [number]},
        (msg) => showImages(msg.images));
    const result = await withTimeout(call.catch((e) => ({error: e})), CHECK_TIMEOUT_SECONDS);
    let report;
    if (result === 'timeout') {
      // The Worker is stuck in the shader: end it and start a fresh one.
      checker.terminate();
      checker = new RaylabWorker();
      report = timeoutReport(exercise);
    } else if (result.error) {
      report = {exercise: exercise.id, number, status: 'CRASH', message: String(result.error.message), hint: '', text:
                exercise.id.padEnd(17) + ' CRASH         ' + result.error.message + '\n'};
    } else {
      report = result.reports[0];
    }
    reports.push(report);
    recordVerdict(exercise.file, checked, report.status);
    markTab(exercise.file);
    $('check-text').textContent += pageReportText(report.text);
  }
  const has = (s) => reports.some((r) => r.status === s);
  let together = null;
  if (numbers.length === state.exercises.length && (has('PASS') || has('FAIL')) &&
      !has('COMPILE ERROR') && !has('TIMEOUT') && !has('CRASH')) {
    const result = await withTimeout(checker.call('together', {files: repositoryFiles()}), CHECK_TIMEOUT_SECONDS);
    together = result === 'timeout' ? null : result.together;
  }
  const togetherOk = !together || together.status === 'PASS';
  if (!togetherOk) $('check-text').textContent += pageReportText(together.text);
  // An optional exercise (a bonus, course/manifest.txt) is counted apart, as `raylab check` does:
  // "10 of 10 exercises pass; optional 11-environment: NOT STARTED".
  const optional = (r) => Boolean((state.exercises.find((e) => e.id === r.exercise) || {}).optional);
  const required = reports.filter((r) => !optional(r));
  const passed = required.filter((r) => r.status === 'PASS').length;
  const bonus = reports.filter(optional).map((r) => '; optional ' + r.exercise + ': ' + r.status).join('');
  const seconds = Math.round((performance.now() - started) / 1000);
  const summary = passed + ' of ' + required.length + ' exercises pass' + bonus +
      (togetherOk ? '' : '; the files do not compile together') + ' (' + seconds + ' s)\n';
  $('check-text').textContent += summary;
  setStatus(passed + ' of ' + required.length + ' pass');
  return {reports, together, text: $('check-text').textContent};
}

// ---- the live picture -----------------------------------------------------------------------
const live = {busy: false, again: false, width: 320, height: 240};
async function drawLive() {
  if (live.busy) { live.again = true; return; }
  live.busy = true;
  try {
    do {
      live.again = false;
      const r = await painter.call('liveFrame', {view: $('view').value});
      if (r.pixels) {
        const image = new ImageData(r.pixels, live.width, live.height);
        $('live').getContext('2d').putImageData(image, 0, 0);
      }
    } while (live.again);
  } catch (e) {
    $('live-error').textContent = String(e.message);
  } finally {
    live.busy = false;
  }
}
async function compileLive() {
  const r = await painter.call('liveCompile', {files: repositoryFiles()});
  $('live-error').textContent = r.error;
  await drawLive();
  return r.error;
}
async function setScene() {
  const r = await painter.call('liveScene', {scene: $('scene').value, width: live.width, height: live.height});
  if (r.error) $('live-error').textContent = r.error;
  await compileLive();
}
function canvasPixel(event) {
  const rect = $('live').getBoundingClientRect();
  return {x: (event.clientX - rect.left) * live.width / rect.width, y: (event.clientY - rect.top) * live.height / rect.height};
}
function wireTrackball() {
  const canvas = $('live');
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    const p = canvasPixel(e);
    // Left drag orbits (Trackball::Mode::Rotate = 0), right or shift drag pans (Pan = 1).
    painter.call('trackball', {action: 'begin', x: p.x, y: p.y, mode: e.button === 0 && !e.shiftKey ? 0 : 1});
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!canvas.hasPointerCapture(e.pointerId)) return;
    const p = canvasPixel(e);
    painter.call('trackball', {action: 'drag', x: p.x, y: p.y});
    drawLive();
  });
  canvas.addEventListener('pointerup', () => painter.call('trackball', {action: 'end'}));
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    painter.call('trackball', {action: 'zoom', steps: -Math.sign(e.deltaY)});
    drawLive();
  }, {passive: false});
}

// ---- download: exercises.zip (stored, no compression), ready for `raylab grade` --------------
const crcTable = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();
function crc32(bytes) {
  let c = 0xFFFFFFFF;
  for (const b of bytes) c = crcTable[(c ^ b) & 0xFF] ^ (c >>> 8);
  return (c ^ 0xFFFFFFFF) >>> 0;
}
// A zip of named byte arrays (PKWARE APPNOTE 4.3: local headers, central directory, end record).
function makeZip(entries) {
  const parts = [], central = [];
  let offset = 0;
  const u16 = (v) => [v & 0xFF, (v >>> 8) & 0xFF];
  const u32 = (v) => [v & 0xFF, (v >>> 8) & 0xFF, (v >>> 16) & 0xFF, (v >>> 24) & 0xFF];
  for (const [name, data] of entries) {
    const nameBytes = new TextEncoder().encode(name);
    const crc = crc32(data);
    // version 2.0, flag bit 11 (UTF-8 names), stored, DOS time 00:00 1 Jan 1980
    const common = [...u16(20), ...u16(0x0800), ...u16(0), ...u16(0), ...u16(0x21), ...u32(crc), ...u32(data.length), ...u32(data.length), ...u16(nameBytes.length), ...u16(0)];
    const local = new Uint8Array([...u32(0x04034b50), ...common]);
    parts.push(local, nameBytes, data);
    central.push(new Uint8Array([...u32(0x02014b50), ...u16(20), ...common, ...u16(0), ...u16(0), ...u16(0), ...u32(0), ...u32(offset)]), nameBytes);
    offset += local.length + nameBytes.length + data.length;
  }
  const size = central.reduce((s, p) => s + p.length, 0);
  const end = new Uint8Array([...u32(0x06054b50), ...u16(0), ...u16(0), ...u16(entries.length), ...u16(entries.length), ...u32(size), ...u32(offset), ...u16(0)]);
  return new Blob([...parts, ...central, end], {type: 'application/zip'});
}
function exercisesZip() {
  const encoder = new TextEncoder();
  return makeZip(state.exercises.map((e) => ['exercises/' + e.file, encoder.encode(repositoryText(e.file, state.files[e.file]))]));
}
function download() {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(exercisesZip());
  a.download = 'exercises.zip';
  document.body.appendChild(a);
  a.click();
  a.remove();
}

// ---- start ----------------------------------------------------------------------------------
async function start() {
  checker = new RaylabWorker();
  painter = new RaylabWorker();
  const hello = await checker.call('hello');
  Object.assign(state, {exercises: hello.exercises, stubs: hello.stubs, context: hello.context});
  for (const e of state.exercises) state.files[e.file] = load(e.file);
  state.editor = CodeMirror($('editor'), {mode: 'x-shader/x-fragment', lineNumbers: true, indentUnit: 4,
                                          matchBrackets: true, value: ''});
  buildTabs();
  wireHandout();
  showFile(state.exercises[0].file);
  markAllTabs();
  let recompile = null;
  state.editor.on('change', () => {
    save(state.current, state.editor.getValue());
    markTab(state.current);
    clearTimeout(recompile);
    recompile = setTimeout(compileLive, 400);  // the live view's hot reload
  });
  $('revert').onclick = () => { if (confirm('Replace ' + state.current + ' with the stub?')) state.editor.setValue(pageStub(state.current)); };
  $('check-all').onclick = () => check();
  $('check-one').onclick = () => runCheckOf(state.exercises.find((e) => e.file === state.current).number);
  $('download').onclick = download;
  $('scene').onchange = setScene;
  $('view').onchange = drawLive;
  $('reset-camera').onclick = () => { painter.call('trackball', {action: 'reset'}); drawLive(); };
  wireTrackball();
  await setScene();
  // Without WebGL2 the editor and the download still work; say why nothing else does.
  setStatus(/^no context/.test(state.context) ? state.context : 'ready');
  $('status').title = state.context;  // which WebGL2 draws: a GPU, SwiftShader, Mesa
  document.body.dataset.ready = 'true';
}

// What the tests drive (tests/browser/): the same functions as the buttons.
window.raylab = {
  state, check, compileLive, exercisesZip,
  setFile(name, text) { if (state.current === name) state.editor.setValue(text); else { save(name, text); markTab(name); } },
  pageStub, pageReportText, showFile,
  compareLive: () => painter.call('compareLive'),
  liveFrame: () => painter.call('liveFrame', {view: $('view').value}),
};
start().catch((e) => { setStatus('failed: ' + e.message); document.body.dataset.ready = 'failed'; console.error(e); });
