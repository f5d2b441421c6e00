// The exercise handouts, rendered for the page at build time (web/make_page.js):
// markdown-it for the Markdown, KaTeX for $...$ and $$...$$ formulas, the
// pictures inlined as data: URLs, links between handouts turned into links
// to the other tab. The page needs no renderer and no network.
//   renderHandouts(listFile) -> {"05-ggx": {path, title, html}, ...}
// listFile: one handout path a line, relative to the repository root
// (written by scripts/build-web.sh, which decides where handouts are).
'use strict';
const fs = require('fs');
const path = require('path');
const MarkdownIt = require('markdown-it');
const katex = require('katex');

// The exercise a handout belongs to: course/05-ggx/handout.md and
// docs/exercises/05-ggx.md are both "05-ggx".
function handoutId(file) {
  const base = path.basename(file, '.md');
  return base === 'handout' ? path.basename(path.dirname(file)) : base;
}

// $...$ (inline) and $$...$$ (a block of its own lines), rendered by KaTeX.
// A dollar sign preceded by a backslash is a dollar sign; "$ 5" (a space
// after the opening one) is not a formula.
function mathPlugin(md) {
  const render = (tex, displayMode) => {
    try {
      return katex.renderToString(tex, {displayMode, throwOnError: true, output: 'html'});
    } catch (e) {
      throw new Error('KaTeX cannot render ' + JSON.stringify(tex) + ': ' + e.message);
    }
  };
  md.inline.ruler.after('escape', 'math_inline', (state, silent) => {
    const src = state.src, start = state.pos;
    if (src[start] !== '$' || src[start + 1] === '$' || /\s/.test(src[start + 1] || ' ')) return false;
    let end = start + 1;
    while ((end = src.indexOf('$', end)) !== -1 && src[end - 1] === '\\') end++;
    if (end === -1 || /\s/.test(src[end - 1])) return false;
    if (!silent) {
      const token = state.push('math_inline', 'span', 0);
      token.content = src.slice(start + 1, end);
    }
    state.pos = end + 1;
    return true;
  });
  md.block.ruler.after('blockquote', 'math_block', (state, startLine, endLine, silent) => {
    const lineText = (n) => state.src.slice(state.bMarks[n] + state.tShift[n], state.eMarks[n]);
    const first = lineText(startLine);
    if (!first.startsWith('$$')) return false;
    if (silent) return true;
    let content = first.slice(2), line = startLine, closed = content.trim().endsWith('$$');
    if (closed) content = content.trim().slice(0, -2);
    while (!closed && ++line < endLine) {
      const text = lineText(line);
      if (text.trim().endsWith('$$')) { content += '\n' + text.trim().slice(0, -2); closed = true; } else content += '\n' + text;
    }
    if (!closed) return false;
    const token = state.push('math_block', 'div', 0);
    token.content = content;
    token.map = [startLine, line + 1];
    state.line = line + 1;
    return true;
  });
  md.renderer.rules.math_inline = (tokens, i) => render(tokens[i].content, false);
  md.renderer.rules.math_block = (tokens, i) => '<div class="math">' + render(tokens[i].content, true) + '</div>\n';
}

const MIME = {'.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.gif': 'image/gif', '.svg': 'image/svg+xml'};

function renderHandout(root, file, ids) {
  const dir = path.dirname(path.join(root, file));
  const md = new MarkdownIt({html: false, linkify: false, typographer: false});
  md.use(mathPlugin);
  // Pictures: inlined. A picture that is not there fails the build (the
  // handout would show a broken image).
  md.renderer.rules.image = (tokens, i, options, env, self) => {
    const token = tokens[i];
    const src = token.attrGet('src');
    if (!/^[a-z]+:/i.test(src)) {
      const picture = path.join(dir, decodeURI(src));
      const mime = MIME[path.extname(picture).toLowerCase()];
      if (!mime || !fs.existsSync(picture)) throw new Error(file + ': picture ' + src + ' not found (' + picture + ')');
      token.attrSet('src', 'data:' + mime + ';base64,' + fs.readFileSync(picture).toString('base64'));
      token.attrSet('data-path', path.relative(root, picture));
    }
    token.attrSet('loading', 'lazy');
    return self.renderToken(tokens, i, options);
  };
  // Links: to another handout, that tab; outside the repository, a new
  // window; to another file of the repository, its path (no page has it).
  const defaultOpen = md.renderer.rules.link_open || ((tokens, i, options, env, self) => self.renderToken(tokens, i, options));
  md.renderer.rules.link_open = (tokens, i, options, env, self) => {
    const token = tokens[i];
    const href = token.attrGet('href') || '';
    if (/^https?:/i.test(href)) {
      token.attrSet('target', '_blank');
      token.attrSet('rel', 'noopener');
    } else if (!href.startsWith('#')) {
      const target = path.relative(root, path.join(dir, href.split('#')[0]));
      const id = handoutId(target);
      if (ids.has(id) && target.endsWith('.md')) {
        token.attrSet('href', '#handout-' + id);
        token.attrSet('data-handout', id);
      } else {
        token.attrSet('href', '#');
        token.attrSet('class', 'repo-link');
        token.attrSet('title', 'in the raylab repository: ' + target);
      }
    }
    return defaultOpen(tokens, i, options, env, self);
  };
  const text = fs.readFileSync(path.join(root, file), 'utf8');
  const title = (text.match(/^# (.*)$/m) || [null, handoutId(file)])[1];
  return {path: file, title, html: md.render(text)};
}

function renderHandouts(root, listFile) {
  const files = fs.readFileSync(listFile, 'utf8').split('\n').map((l) => l.trim()).filter(Boolean);
  const ids = new Set(files.map(handoutId));
  const out = {};
  for (const file of files) out[handoutId(file)] = renderHandout(root, file, ids);
  return out;
}

// KaTeX's style sheet with its WOFF2 fonts inlined (every browser the page
// supports reads WOFF2; the WOFF and TTF copies are left out).
function katexCss() {
  const dist = path.join(path.dirname(require.resolve('katex')), '');
  const css = fs.readFileSync(path.join(dist, 'katex.min.css'), 'utf8');
  return css.replace(/src:([^;}]*)/g, (all, sources) => {
    const woff2 = sources.match(/url\((fonts\/[^)]+\.woff2)\)/);
    if (!woff2) return all;
    const data = fs.readFileSync(path.join(dist, woff2[1])).toString('base64');
    return 'src:url(data:font/woff2;base64,' + data + ') format("woff2")';
  });
}

module.exports = {renderHandouts, renderHandout, handoutId, katexCss};
