// The handouts' rendering for the page (web/handouts.js), without a browser:
// formulas through KaTeX, pictures inlined, links between handouts.
//   node tests/browser/handouts_test.js
// Exit 0 when every assertion holds; each failure is one line on stderr.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');

const root = path.resolve(__dirname, '../..');
const {renderHandouts, katexCss} = require(path.join(root, 'web/handouts.js'));
const failures = [];
const expect = (ok, what) => { if (!ok) failures.push(what); };

// A course of two handouts in the layout the lead moves to (course/NN-name/handout.md).
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'rl-handouts-'));
fs.mkdirSync(path.join(dir, 'course/05-ggx/images'), {recursive: true});
fs.mkdirSync(path.join(dir, 'course/06-geometry'), {recursive: true});
fs.copyFileSync(path.join(root, 'docs/images/grading-report.png'), path.join(dir, 'course/05-ggx/images/d.png'));
fs.writeFileSync(path.join(dir, 'course/05-ggx/handout.md'), [
  '# Exercise 05: D', '',
  'Inline $D = \\frac{\\alpha^2}{\\pi\\,((n\\cdot h)^2(\\alpha^2-1)+1)^2}$ and a price of \\$5.', '',
  '$$', '\\int_{\\Omega} D(m)\\,(n\\cdot m)\\,dm = 1', '$$', '',
  '![the D view](images/d.png)', '',
  'Next: [exercise 06](../06-geometry/handout.md); see [numerics](../../docs/numerics.md) and [Walter](https://example.org/w).', '',
  '    D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)', ''].join('\n'));
fs.writeFileSync(path.join(dir, 'course/06-geometry/handout.md'), '# Exercise 06: G\n');
fs.writeFileSync(path.join(dir, 'list.txt'), 'course/05-ggx/handout.md\ncourse/06-geometry/handout.md\n');
const h = renderHandouts(dir, path.join(dir, 'list.txt'));
const html = h['05-ggx'] && h['05-ggx'].html;
expect(html && h['06-geometry'], 'handouts by exercise id: ' + Object.keys(h));
expect(h['05-ggx'].title === 'Exercise 05: D', 'title: ' + h['05-ggx'].title);
expect((html.match(/class="katex"/g) || []).length === 2, 'two formulas rendered by KaTeX');
expect(/class="katex-display"/.test(html), 'the $$ block is a display formula');
expect(html.includes('price of $5'), 'an escaped dollar stays a dollar');
expect(/<img src="data:image\/png;base64,[A-Za-z0-9+/]+=*"/.test(html), 'the picture is inlined');
expect(/href="#handout-06-geometry" data-handout="06-geometry"/.test(html), 'a link to another handout opens its tab');
expect(/class="repo-link" title="in the raylab repository: docs\/numerics.md"/.test(html), 'a repository link keeps its path');
expect(/href="https:\/\/example.org\/w" target="_blank"/.test(html), 'an outside link opens a new window');
expect(html.includes('<pre><code>D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)'), 'an indented formula stays as written');
// A picture that is not there fails the build.
fs.writeFileSync(path.join(dir, 'course/06-geometry/handout.md'), '# G\n\n![gone](images/gone.png)\n');
let refused = '';
try { renderHandouts(dir, path.join(dir, 'list.txt')); } catch (e) { refused = e.message; }
expect(/course\/06-geometry\/handout.md: picture images\/gone.png not found/.test(refused), 'a missing picture: ' + refused);
// KaTeX's fonts travel inside the page.
const css = katexCss();
expect(!/url\(fonts\//.test(css) && /url\(data:font\/woff2;base64,/.test(css), 'KaTeX fonts inlined');
// The repository's own handouts render (scripts/build-web.sh's list).
const list = path.join(root, 'build-web/generated/handouts.txt');
if (fs.existsSync(list)) {
  const all = renderHandouts(root, list);
  // One per unit of the course's manifest.
  const units = fs.readFileSync(path.join(root, 'course/manifest.txt'), 'utf8')
    .split('\n').map((l) => l.replace(/#.*/, '').trim()).filter((l) => l).length;
  expect(Object.keys(all).length === units, 'the repository has ' + Object.keys(all).length + ' handouts, the manifest ' + units + ' units');
}
fs.rmSync(dir, {recursive: true, force: true});
for (const f of failures) console.error('FAIL: ' + f);
console.log(failures.length ? failures.length + ' failed' : 'handouts: all hold');
process.exit(failures.length ? 1 : 0);
