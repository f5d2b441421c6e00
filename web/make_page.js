// Writes raylab-web.html: web/page.html with everything inlined (the compiled
// module as base64, CodeMirror's built files, the page's CSS and JS, the
// Worker's JS), so the one file opens from file:// with no network.
//   node web/make_page.js build-web/raylab.js build-web/raylab-web.html
'use strict';
const fs = require('fs');
const path = require('path');

const [moduleJs, output] = process.argv.slice(2);
const here = __dirname;
const read = (p) => fs.readFileSync(path.join(here, p), 'utf8');
const cm = (p) => read(path.join('node_modules/codemirror', p));

// Inside a <script> element the HTML parser ends at "</script"; inside
// <style>, at "</style". None of the inlined texts may hold them.
function inlineSafe(text, what, closing) {
  if (text.toLowerCase().includes(closing)) throw new Error(what + ' contains ' + closing + ': cannot inline it');
  return text;
}

const worker = read('worker.js');
const pageJs = read('page.js').replace("/*@WORKER_JS@*/''", () => JSON.stringify(worker));
const codemirrorJs = [cm('lib/codemirror.js'), cm('mode/clike/clike.js'), cm('addon/edit/matchbrackets.js')].join('\n;\n');
const moduleB64 = 'const RAYLAB_MODULE_B64 = "' + fs.readFileSync(moduleJs).toString('base64') + '";';

const parts = {
  '/*@CODEMIRROR_CSS@*/': inlineSafe(cm('lib/codemirror.css'), 'codemirror.css', '</style'),
  '/*@PAGE_CSS@*/': inlineSafe(read('page.css'), 'page.css', '</style'),
  '/*@RAYLAB_MODULE_B64@*/': moduleB64,
  '/*@CODEMIRROR_JS@*/': inlineSafe(codemirrorJs, 'CodeMirror', '</script'),
  '/*@PAGE_JS@*/': inlineSafe(pageJs, 'page.js', '</script'),
};
let html = read('page.html');
for (const [marker, text] of Object.entries(parts)) {
  if (!html.includes(marker)) throw new Error('page.html lacks ' + marker);
  html = html.replace(marker, () => text);
}
const temporary = output + '.tmp';
fs.writeFileSync(temporary, html);
fs.renameSync(temporary, output);  // never a half-written page
