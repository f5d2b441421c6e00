#!/usr/bin/env python3
"""The leak detector that attacks (issue 35): every function of every GLSL
file of TREE's framework (shaders/, recursively) and of every ```glsl block
of its documents (handouts included) whose return and parameter
types are those of an exercise function of the course is renamed to that
function, put into the exercise's shipped stub in place of it, and checked
by the instructor's program against that exercise's probes. A function that
passes every probe case of the exercise function is a copy of the answer,
however it is named or laid out: one line each,

    shaders/FILE.glsl: NAME passes all N probe cases of EXERCISE's FUNCTION

and exit status 1. Exit status 0 when none passes (a candidate that does not
compile, or fails a case, is no leak).

    scripts/attack-leaks.py RAYLAB TREE SCRATCH

RAYLAB is the instructor's program (its checker has the probes); TREE the
edition (scripts/student-edition.sh runs this on it before the commit);
SCRATCH a folder for the candidates' files.
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from glsl_functions import COMMENTS, HEADER, definitions  # noqa: E402

QUALIFIERS = {'in', 'const', 'highp', 'mediump', 'lowp'}


def param_types(params):
    """The parameters' types, qualifiers that do not change the call dropped: ['vec3', 'out float']."""
    out = []
    for p in params.split(','):
        words = [w for w in p.split() if w not in QUALIFIERS]
        if words:
            out.append(' '.join(words[:-1]))
    return tuple(out)


def functions(text):
    """(return type, name, parameter types, whole definition) of each top-level function."""
    text, found = definitions(text)
    return [(m.group(1), m.group(2), param_types(m.group(3)), text[m.start():end]) for m, end in found]


def course(tree):
    """(unit, function name, return type, parameter types) of each exercise function."""
    units = []
    for line in open(os.path.join(tree, 'course', 'manifest.txt'), encoding='utf-8'):
        words = line.split('#', 1)[0].split()
        if words:
            units.append(words[0])
    out = []
    for unit in units:
        data = json.load(open(os.path.join(tree, 'course', unit, 'unit.json'), encoding='utf-8'))
        for f in data['functions']:
            m = HEADER.match(f['signature'].strip() + ' {')
            if m:
                out.append((unit, m.group(2), m.group(1), param_types(m.group(3))))
    return out


def main():
    raylab, tree, scratch = sys.argv[1:4]
    os.makedirs(scratch, exist_ok=True)
    targets = course(tree)
    leaks, tried = 0, 0
    sources = []  # (shown path, GLSL text)
    for folder, dirs, files in os.walk(tree):
        dirs[:] = [d for d in dirs if not d.startswith(('.', 'build')) and d != 'node_modules']
        rel = os.path.relpath(folder, tree)
        for name in sorted(files):
            path = os.path.join(folder, name)
            if name.endswith(('.glsl', '.frag')) and (rel == 'shaders' or rel.startswith('shaders' + os.sep)):
                sources.append((os.path.relpath(path, tree), open(path, encoding='utf-8').read()))
            elif name.endswith('.md'):
                # A document's GLSL blocks: a handout may state a formula, not a body.
                blocks = re.findall(r'^```glsl\n(.*?)^```', open(path, encoding='utf-8').read(), re.S | re.M)
                if blocks:
                    sources.append((os.path.relpath(path, tree), '\n'.join(blocks)))
    for shown, text in sources:
            for ret, fname, types, definition in functions(text):
                for unit, target, tret, ttypes in targets:
                    if (ret, types) != (tret, ttypes) or fname == target:
                        continue
                    stub = open(os.path.join(tree, 'course', unit, 'stub.glsl'), encoding='utf-8').read()
                    own = [d for r, n, t, d in functions(stub) if n == target]
                    if not own:
                        continue
                    candidate = re.sub(r'\b%s\b' % re.escape(fname), target, definition)
                    tried += 1
                    file = os.path.join(scratch, '%d-%s.glsl' % (tried, unit))
                    with open(file, 'w', encoding='utf-8') as out:
                        out.write(COMMENTS.sub('', stub).replace(own[0], candidate))
                    report = os.path.join(scratch, '%d.json' % tried)
                    subprocess.run([raylab, 'check', '-e', unit, '--file', file, '--json', report, '--output',
                                    os.path.join(scratch, 'out')], stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL, timeout=300)
                    if not os.path.exists(report):
                        continue
                    for exercise in json.load(open(report)).get('exercises', []):
                        for probe in exercise.get('probes', []):
                            if probe.get('name') == target and probe.get('total', 0) > 0 and \
                                    probe.get('passed') == probe.get('total'):
                                print('%s: %s passes all %d probe cases of %s\'s %s'
                                      % (shown, fname, probe['total'], unit, target))
                                leaks += 1
    print('attack-leaks.py: %d framework functions tried as exercise functions, %d pass' % (tried, leaks),
          file=sys.stderr)
    return 1 if leaks else 0


if __name__ == '__main__':
    sys.exit(main())
