#!/usr/bin/env python3
"""The course's files, checked when the build configures (cmake/course.cmake
runs it before it reads them): every folder of course/, its unit.json against
course/unit.schema.json (JSON Schema draft-07, with Debian's
python3-jsonschema, as the scene files are), and course/manifest.txt byte
for byte. Prints one line for the first mistake, naming the file, the line
where there is one, and the field, and exits 1; prints nothing and exits 0
when the course is sound.

    cmake/validate_course.py COURSE_DIR

What it refuses, beyond the schema (types, ranges, unknown fields): a folder
not named NN-name (two digits, a dash, lower-case letters, digits and
dashes: no space, quote or semicolon, which the generated C++ and CMake's
lists cannot carry), a unit without unit.json or stub.glsl, two units with
one number, a function two units define, a signature that does not declare
its function, a "needs" naming no unit's function, a unit.json that is not
exactly one JSON value (trailing text, a repeated key, a byte-order mark),
and a manifest that is not plain UTF-8 text (a byte-order mark, a control
character) or whose line names no unit or adds a word other than
"optional".
"""
import json
import os
import re
import sys

NAME = re.compile(r'^[0-9]{2}-[a-z0-9]+(-[a-z0-9]+)*$')
MAX_DEPTH = 64  # as the program's JSON reader (app/core/json_text.h)


class Mistake(Exception):
    pass


def shown(text):
    """A name as a message may show it: quoted, control characters escaped, cut."""
    out = json.dumps(text, ensure_ascii=True)
    return out if len(out) <= 60 else out[:57] + '..."'


def line_of(text, path):
    """The line of the field `path` (a list of keys and indexes): the line of the
    last key's occurrence, counting occurrences as the indexes before it say."""
    keys = [p for p in path if isinstance(p, str)]
    if not keys:
        return 1
    key = keys[-1]
    index = next((p for p in reversed(path) if isinstance(p, int)), 0)
    hits = [m.start() for m in re.finditer(r'"%s"\s*:' % re.escape(key), text)]
    if not hits:
        return 1
    at = hits[min(index, len(hits) - 1)]
    return text.count('\n', 0, at) + 1


def field_name(path):
    out = ''
    for p in path:
        out += '[%d]' % p if isinstance(p, int) else ('.' if out else '') + p
    return out


def no_duplicate_keys(pairs):
    seen = set()
    for key, _ in pairs:
        if key in seen:
            raise ValueError('the key "%s" appears twice' % key)
        seen.add(key)
    return dict(pairs)


def load_unit(course, unit, validator):
    where = 'course/%s/unit.json' % unit
    raw = open(os.path.join(course, unit, 'unit.json'), 'rb').read()
    if raw.startswith(b'\xef\xbb\xbf'):
        raise Mistake('%s:1: starts with a byte-order mark: save it as UTF-8 without one' % where)
    try:
        text = raw.decode('utf-8')
    except UnicodeDecodeError as e:
        raise Mistake('%s:%d: not UTF-8 text (byte %d)' % (where, raw.count(b'\n', 0, e.start) + 1, e.start))
    depth, deepest, in_string, escaped = 0, 0, False, False
    for at, c in enumerate(text):  # nesting first: json and jsonschema recurse
        if in_string:
            escaped, in_string = (not escaped and c == '\\'), in_string and (escaped or c != '"')
        elif c == '"':
            in_string = True
        elif c in '[{':
            depth += 1
            if depth > MAX_DEPTH:
                raise Mistake('%s:%d: values nest more than %d deep' % (where, text.count('\n', 0, at) + 1, MAX_DEPTH))
        elif c in ']}':
            depth -= 1
    try:
        data = json.loads(text, object_pairs_hook=no_duplicate_keys)
    except json.JSONDecodeError as e:
        what = 'text after the JSON value' if e.msg == 'Extra data' else e.msg
        raise Mistake('%s:%d:%d: not one JSON value: %s' % (where, e.lineno, e.colno, what))
    except ValueError as e:
        raise Mistake('%s: %s' % (where, e))
    errors = sorted(validator.iter_errors(data), key=lambda e: (len(e.path), list(map(str, e.path))))
    if errors:
        e = errors[0]
        path = list(e.path)
        if e.validator == 'additionalProperties':
            unknown = sorted(set(e.instance) - set(e.schema.get('properties', {})))
            path = path + [unknown[0]] if unknown else path
            allowed = ', '.join(sorted(e.schema.get('properties', {})))
            message = 'unknown field (the fields are %s)' % allowed
        elif e.validator == 'required':
            missing = [k for k in e.validator_value if k not in e.instance]
            path = path + missing[:1]
            message = 'missing (a unit needs it)' if len(path) == 1 else 'missing (every function needs it)'
        elif e.validator == 'oneOf':
            message = '%s must be a string or an array of lines' % shown_value(e.instance)
        else:
            message = '%s: %s' % (shown_value(e.instance), schema_words(e))
        name = field_name(path)
        raise Mistake('%s:%d: %s%s' % (where, line_of(text, path), name + ': ' if name else '', message))
    return data


def shown_value(value):
    text = json.dumps(value)
    return text if len(text) <= 40 else text[:37] + '...'


def schema_words(e):
    if e.validator == 'type':
        return 'must be %s' % {'integer': 'a whole number', 'boolean': 'true or false', 'string': 'a string',
                               'array': 'an array', 'object': 'an object'}.get(e.validator_value, e.validator_value)
    if e.validator == 'minimum':
        return 'must be at least %s' % e.validator_value
    if e.validator == 'maximum':
        return 'must be at most %s' % e.validator_value
    if e.validator == 'pattern':
        return 'does not match %s' % e.validator_value
    if e.validator in ('minLength', 'minItems'):
        return 'must not be empty'
    return e.message[:160]


def check_manifest(course, units):
    where = 'course/manifest.txt'
    raw = open(os.path.join(course, 'manifest.txt'), 'rb').read()
    if raw.startswith(b'\xef\xbb\xbf'):
        raise Mistake('%s:1: starts with a byte-order mark (invisible): save it as UTF-8 without one' % where)
    try:
        text = raw.decode('utf-8')
    except UnicodeDecodeError as e:
        raise Mistake('%s:%d: not UTF-8 text (byte %d)' % (where, raw.count(b'\n', 0, e.start) + 1, e.start))
    listed = set()
    for number, line in enumerate(text.split('\n'), 1):
        bad = re.search(r'[\x00-\x08\x0b\x0c\x0e-\x1f\x7f\u00a0\u200b\ufeff]', line)
        if bad:
            raise Mistake('%s:%d: holds the control or invisible character U+%04X' % (where, number, ord(bad.group())))
        words = line.split('#', 1)[0].split()
        if not words:
            continue
        unit = words[0]
        if not NAME.match(unit):
            raise Mistake('%s:%d: %s is no unit name (two digits, a dash, lower-case letters, digits and dashes, '
                          'like NN-name)' % (where, number, shown(' '.join(words))))
        if unit not in units:
            raise Mistake('%s:%d: no unit %s (course/%s/unit.json is missing)' % (where, number, unit, unit))
        if words[1:] and words[1:] != ['optional']:
            raise Mistake('%s:%d: %s after the unit name: only "optional" may follow it'
                          % (where, number, shown(' '.join(words[1:]))))
        if unit in listed:
            raise Mistake('%s:%d: %s is listed twice' % (where, number, unit))
        listed.add(unit)
    if not listed:
        raise Mistake('%s lists no unit' % where)


def main():
    course = sys.argv[1]
    try:
        import jsonschema
    except ImportError:
        print('cmake/validate_course.py: needs python3-jsonschema (scripts/setup.sh installs it)')
        return 1
    schema = json.load(open(os.path.join(course, 'unit.schema.json'), encoding='utf-8'))
    validator = jsonschema.Draft7Validator(schema)
    try:
        units = {}
        for entry in sorted(os.listdir(course)):
            if not os.path.isdir(os.path.join(course, entry)):
                continue
            if not NAME.match(entry):
                raise Mistake('course/%s: a unit folder is named NN-name (two digits, a dash, lower-case letters, '
                              'digits and dashes, like NN-name), not %s' % (entry, shown(entry)))
            for required in ('unit.json', 'stub.glsl'):
                if not os.path.isfile(os.path.join(course, entry, required)):
                    raise Mistake('course/%s/%s is missing (every unit has one; docs/instructor.md, '
                                  '"Adding an exercise")' % (entry, required))
            units[entry] = load_unit(course, entry, validator)
        numbers, owner = {}, {}
        for unit, data in units.items():
            if unit[:2] in numbers:
                raise Mistake('course/%s: has the number %s of course/%s (raylab check --exercise %s would not '
                              'know which)' % (unit, unit[:2], numbers[unit[:2]], unit[:2]))
            numbers[unit[:2]] = unit
            for k, f in enumerate(data['functions']):
                if f['name'] in owner:
                    raise Mistake('course/%s/unit.json: functions[%d].name: %s is a function of course/%s too'
                                  % (unit, k, f['name'], owner[f['name']]))
                owner[f['name']] = unit
                if not re.search(r'\b%s\s*\(' % re.escape(f['name']), f['signature']):
                    raise Mistake('course/%s/unit.json: functions[%d].signature: does not declare %s(...)'
                                  % (unit, k, f['name']))
        for unit, data in units.items():
            for k, f in enumerate(data['functions']):
                for field in ('needs', 'framework_calls'):
                    for need in f.get(field, []):
                        if need not in owner:
                            raise Mistake('course/%s/unit.json: functions[%d].%s: %s is no unit\'s function'
                                          % (unit, k, field, need))
            for s, strategy in enumerate(data.get('bench_strategies', [])):
                if not os.path.isfile(os.path.join(course, unit, strategy['mutant'])) and \
                        os.path.isdir(os.path.join(course, unit, 'mutants')):
                    raise Mistake('course/%s/unit.json: bench_strategies[%d].mutant: course/%s/%s is missing'
                                  % (unit, s, unit, strategy['mutant']))
        check_manifest(course, units)
    except Mistake as m:
        print(m)
        return 1
    except (OSError, RecursionError, ValueError) as e:  # what no rule above foresaw: still one line
        print('course/: cannot be checked: %s' % str(e).splitlines()[0][:200] if str(e) else type(e).__name__)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
