#!/usr/bin/env python3
"""No file outside course/ names a unit: the framework asks the registry
(app/course/exercise_registry.h) for what a unit provides, never for a unit
by its folder name (issue 35). Searches the code of app/, shaders/, web/,
cmake/, scripts/ and CMakeLists.txt, comments left out (an example in a
comment names no dependency), for the folder name of every unit in course/,
and a unit's path (course/NN-...). Prints `file:line: names UNIT` for each and
exits 1 when there is one.

    tests/course/no_unit_outside_course.py SOURCE_ROOT
"""
import os
import re
import sys

root = sys.argv[1]
units = sorted(d for d in os.listdir(os.path.join(root, 'course'))
               if os.path.isdir(os.path.join(root, 'course', d)))
if not units:
    print('no unit folder in %s/course' % root)
    sys.exit(1)
named = re.compile(r'(?<![\w.-])(%s)(?![\w-])|course/[0-9]{2}-' % '|'.join(map(re.escape, units)))
C_LIKE = {'.cpp', '.h', '.in', '.glsl', '.frag', '.vert', '.js', '.mjs'}
HASH = {'.py', '.sh', '.cmake', '.txt'}
C_COMMENTS = re.compile(r'//[^\n]*|/\*.*?\*/', re.S)
HASH_COMMENT = re.compile(r'(?m)(^|\s)#(?![!{]).*$')
PY_DOC = re.compile(r'"""[^"]*?"""', re.S)


def code_of(path, text):
    ext = os.path.splitext(path)[1]
    if ext in C_LIKE:
        # comments out, line count kept
        return C_COMMENTS.sub(lambda m: '\n' * m.group().count('\n'), text)
    if ext in HASH or os.path.basename(path) == 'CMakeLists.txt':
        if ext == '.py':
            text = PY_DOC.sub(lambda m: '\n' * m.group().count('\n'), text)
        return HASH_COMMENT.sub(lambda m: m.group(1), text)
    return None


found = 0
for top in ('app', 'shaders', 'web', 'cmake', 'scripts', 'CMakeLists.txt'):
    start = os.path.join(root, top)
    paths = [start] if os.path.isfile(start) else [
        os.path.join(d, f) for d, dirs, files in os.walk(start) for f in files
        if 'node_modules' not in d]
    for path in sorted(paths):
        try:
            text = open(path, encoding='utf-8').read()
        except (UnicodeDecodeError, OSError):
            continue
        code = code_of(path, text)
        if code is None:
            continue
        for number, line in enumerate(code.split('\n'), 1):
            m = named.search(line)
            if m:
                print('%s:%d: names %s' % (os.path.relpath(path, root), number, m.group(1) or m.group()))
                found += 1
if found:
    print('%d line(s) outside course/ name a unit: ask the registry instead (course/README.md)' % found)
sys.exit(1 if found else 0)
