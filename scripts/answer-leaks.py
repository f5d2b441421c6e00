#!/usr/bin/env python3
"""Answers left in a tree: every function body of SOLUTIONS/*.glsl, with
comments and white space dropped, searched for in the text of every file of
TREE that a student reads (.glsl, .md, .cpp, .h, .js, .py, .sh, .txt, .json,
.html), app/ included. Prints one line per leak, `file: the body of NAME
(solutions/FILE)`, and exits 1 when there is one, 0 when there is none.

app/ is searched too: a student edition has no CPU reference in it (the
export leaves app/reference/'s model out and ships what the checker needs as
recorded data; docs/instructor.md, "A student edition").

    scripts/answer-leaks.py SOLUTIONS_DIR TREE

scripts/student-edition.sh runs it on the edition before committing it; the
test `edition.StudentEdition` runs it again on the export.

A file is searched twice: with its comments dropped (the code as compiled)
and with only the comment markers dropped (code quoted inside a comment or
a handout's prose). Bodies shorter than MIN_BODY characters (after
normalising) are not searched: `return x;` names no answer, and every
solution body is longer (the shortest, Fd_Lambert's, is 16).
"""
import os
import re
import sys

MIN_BODY = 12
SKIP_TOP = {'build', 'build-headless', 'build-glfw', 'build-asan', 'build-web', 'node_modules'}
EXTENSIONS = {'.glsl', '.frag', '.vert', '.md', '.cpp', '.h', '.js', '.mjs', '.py', '.sh', '.txt', '.json',
              '.html', '.in', '.cmake'}
WHITE = re.compile(r'\s+')
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from glsl_functions import COMMENTS, definitions  # noqa: E402


def code_form(text):
    """No comments, no white space: what two equal pieces of code share."""
    return WHITE.sub('', COMMENTS.sub('', text))


def quoted_form(text):
    """No comment markers, no white space: code quoted in a comment or in prose."""
    return WHITE.sub('', text.replace('/*', '').replace('*/', '').replace('//', ''))


def bodies(path):
    """(function name, normalised body) for each top-level function of a GLSL file."""
    text, found = definitions(open(path, encoding='utf-8').read())
    return [(m.group(2), WHITE.sub('', text[m.end():i - 1])) for m, i in found]


def main():
    if len(sys.argv) != 3:
        sys.exit('usage: answer-leaks.py SOLUTIONS_DIR TREE')
    solutions, tree = sys.argv[1], sys.argv[2]
    answers = []
    for name in sorted(os.listdir(solutions)):
        if name.endswith('.glsl'):
            answers += [(f, name, body) for f, body in bodies(os.path.join(solutions, name)) if len(body) >= MIN_BODY]
    if not answers:
        sys.exit(f'answer-leaks.py: {solutions}: no function bodies found')
    leaks = 0
    for root, dirs, files in os.walk(tree):
        dirs[:] = sorted(d for d in dirs if d != '.git' and not (root == tree and d in SKIP_TOP))
        for name in sorted(files):
            if os.path.splitext(name)[1] not in EXTENSIONS:
                continue
            path = os.path.join(root, name)
            try:
                text = open(path, encoding='utf-8', errors='replace').read()
            except OSError as e:
                sys.exit(f'answer-leaks.py: {path}: {e.strerror}')
            forms = (code_form(text), quoted_form(text))
            for function, source, body in answers:
                if any(body in form for form in forms):
                    print(f'{os.path.relpath(path, tree)}: the body of {function} (solutions/{source})')
                    leaks += 1
    return 1 if leaks else 0


if __name__ == '__main__':
    sys.exit(main())
