"""The top-level functions of a GLSL text, as the edition's leak checks read
them (scripts/answer-leaks.py: every solution body searched for;
scripts/attack-leaks.py: every framework function tried as an exercise's)."""
import re

COMMENTS = re.compile(r'//[^\n]*|/\*.*?\*/', re.S)
# "type name(parameters) {" at the start of a line: return type, name, parameters.
HEADER = re.compile(r'^[ \t]*([A-Za-z_]\w*)[ \t]+([A-Za-z_]\w*)[ \t]*\(([^)]*)\)\s*\{', re.M)


def definitions(text):
    """(header match, end) of each top-level function of `text` with its comments
    removed, and that text: the body runs from match.end() to end - 1 (its
    closing brace), the whole definition from match.start() to end."""
    text = COMMENTS.sub('', text)
    out = []
    for m in HEADER.finditer(text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {'{': 1, '}': -1}.get(text[i], 0)
            i += 1
        out.append((m, i))
    return text, out
