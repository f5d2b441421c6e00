// raylab-web's Worker: one instance of the compiled C++ (createRaylab, from
// scripts/build-web.sh) with its own WebGL2 context on an OffscreenCanvas.
// The page starts two: one checks, one draws the live picture, so a check
// never stalls the trackball and a stuck check can be ended with terminate().
// Messages in: {id, op, ...}; out: {id, ok, ...} (and {id, progress} while checking).
'use strict';

let raylab = null;
const ready = createRaylab({print: () => {}, printErr: (t) => console.warn(t)}).then((m) => { raylab = m; });

// The student's files, written where the native checker reads them.
function writeFiles(files) {
  for (const [name, text] of Object.entries(files || {})) {
    if (!/^[0-9][0-9]-[a-z-]+\.glsl$/.test(name)) continue;  // exercise files only
    raylab.FS.writeFile('/raylab/exercises/' + name, text);
  }
}

// A file the checker wrote, by the path its report names (relative to /raylab).
function readIfThere(path) {
  try {
    return raylab.FS.readFile(path);
  } catch (e) {
    console.warn('raylab-web: cannot read ' + path + ' in ' + raylab.FS.cwd() + ': ' + e);
    return null;
  }
}

// Pictures of a report (written by the checker into check-output/), as PNG bytes.
function imagesOf(report) {
  const out = {};
  for (const image of report.images || []) {
    for (const kind of ['expected', 'got', 'diff']) {
      if (image[kind]) {
        const bytes = readIfThere(image[kind]);
        if (bytes) out[image[kind]] = bytes;
      }
    }
  }
  return out;
}

function removeTree(path) {
  const FS = raylab.FS;
  let stat;
  try { stat = FS.stat(path); } catch (e) { return; }
  if (FS.isDir(stat.mode)) {
    for (const entry of FS.readdir(path)) if (entry !== '.' && entry !== '..') removeTree(path + '/' + entry);
    FS.rmdir(path);
  } else {
    FS.unlink(path);
  }
}

const ops = {
  hello() {
    const stubs = {};
    const exercises = JSON.parse(raylab.exerciseList());
    for (const e of exercises) stubs[e.file] = raylab.FS.readFile('/raylab/exercises/' + e.file, {encoding: 'utf8'});
    return {exercises, stubs, context: raylab.contextDescription()};
  },
  // As `raylab check --exercise N...`: each exercise's report, with its pictures.
  check(msg, post) {
    writeFiles(msg.files);
    removeTree('check-output');  // this check's pictures only
    const reports = [];
    for (const number of msg.exercises) {
      const report = JSON.parse(raylab.checkOne(number));
      reports.push(report);
      post({progress: report, images: imagesOf(report)});
    }
    return {reports};
  },
  // The last step of `raylab check`: the ten files compiled together.
  together(msg) {
    writeFiles(msg.files);
    return {together: JSON.parse(raylab.checkTogether())};
  },
  liveScene(msg) { return {error: raylab.setScene(msg.scene || '', msg.width, msg.height)}; },
  liveCompile(msg) {
    writeFiles(msg.files);
    return {error: raylab.compileLive()};
  },
  liveFrame(msg) {
    const pixels = raylab.renderLive(msg.view || 'final');
    return {pixels: pixels ? new Uint8ClampedArray(pixels) : null};
  },
  trackball(msg) {
    if (msg.action === 'begin') raylab.trackballBegin(msg.x, msg.y, msg.mode || 0);
    else if (msg.action === 'drag') raylab.trackballDrag(msg.x, msg.y);
    else if (msg.action === 'end') raylab.trackballEnd();
    else if (msg.action === 'zoom') raylab.trackballZoom(msg.steps);
    else if (msg.action === 'reset') raylab.trackballReset();
    return {};
  },
  compareLive() { return JSON.parse(raylab.compareLiveWithReference()); },
  // The pixel debugger at (x, y) from the top left of the live picture (the files of the last liveCompile).
  askPixel(msg) { return JSON.parse(raylab.askPixel(msg.x, msg.y)); },
};

self.onmessage = async (event) => {
  const msg = event.data;
  await ready;
  const post = (extra) => self.postMessage(Object.assign({id: msg.id}, extra));
  try {
    const result = ops[msg.op](msg, post);
    const transfer = result && result.pixels ? [result.pixels.buffer] : [];
    self.postMessage(Object.assign({id: msg.id, ok: true, done: true}, result), transfer);
  } catch (e) {
    post({ok: false, done: true, error: String(e && e.message ? e.message : e)});
  }
};
