// Writes raylab-web.html: web/page.html with everything inlined (the compiled
// module as base64, CodeMirror's built files, the page's CSS and JS, the
// Worker's JS, the handouts rendered with KaTeX's style sheet and fonts), so
// the one file opens from file:// with no network.
//   node web/make_page.js build-web/raylab.js build-web/raylab-web.html HANDOUT_LIST
// HANDOUT_LIST: the handouts' paths, one a line (scripts/build-web.sh writes it).
'use strict';
const fs = require('fs');
const path = require('path');

const [moduleJs, output, handoutList] = process.argv.slice(2);
const {renderHandouts, katexCss} = require('./handouts.js');
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
// JSON inside a <script>: "</" written as "<\/" (the same string to JavaScript).
const handouts = 'const RAYLAB_HANDOUTS = ' +
    JSON.stringify(renderHandouts(path.resolve(here, '..'), handoutList)).replace(/<\//g, '<\\/') + ';';
const moduleB64 = 'const RAYLAB_MODULE_B64 = "' + fs.readFileSync(moduleJs).toString('base64') + '";';

const parts = {
  '/*@CODEMIRROR_CSS@*/': inlineSafe(cm('lib/codemirror.css'), 'codemirror.css', '</style'),
  '/*@KATEX_CSS@*/': inlineSafe(katexCss(), 'katex.min.css', '</style'),
  '/*@HANDOUTS_JS@*/': inlineSafe(handouts, 'the handouts', '</script'),
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
