#!/usr/bin/env python3
"""Checks the shape we keep the code in, so that it stays that way:
- every file of the command-line front end (cli/) is at most 300 lines;
- every function in the run library (run/) is at most 80 lines.

Functions are found by brace depth outside namespaces: a body opens where a '{' takes the depth
from 0 to 1 on a line that does not open a namespace, class, struct, enum or union, and closes
where the depth returns to 0. Strings, character literals and comments are blanked first so their
braces do not count. Lambdas and local classes count towards the function that holds them.
Usage: check_code_shape.py SOURCE_DIR   (exit 1 and one line per offence)"""
import pathlib
import re
import sys

MAX_CLI_FILE_LINES = 300
MAX_RUN_FUNCTION_LINES = 80
TYPE_OPENER = re.compile(r'^\s*(template\s*<.*>\s*)?(namespace|class|struct|enum|union)\b')


def blank_literals_and_comments(text):
    """The text with comments, strings and character literals replaced by spaces (lines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def long_functions(path, limit):
    """(first line, length) of every function body in `path` longer than `limit` lines."""
    lines = blank_literals_and_comments(path.read_text()).split('\n')
    found, stack, start = [], [], None  # stack: True for a namespace/type brace, False otherwise
    for number, line in enumerate(lines, 1):
        for ch in line:
            if ch == '{':
                opener = start is None and bool(TYPE_OPENER.match(line))
                if start is None and not opener:
                    start = number  # a function body at namespace or class level
                    stack.append(False)
                else:
                    stack.append(opener if start is None else False)
            elif ch == '}' and stack:
                stack.pop()
                if start is not None and all(stack):
                    if number - start + 1 > limit:
                        found.append((start, number - start + 1))
                    start = None
    return found


def self_test():
    """The checker itself: a namespace, a class and a lambda do not hide an 81-line function,
    and braces in strings and comments do not count."""
    import tempfile
    body = '\n'.join(['  x += 1;  // }'] * 78)
    source = ('namespace cosim {\nstruct S {\n  int f() const { return 1; }\n};\n'
              'int g(int x) {\n  auto l = [] { return "{"; };\n' + body + '\n}\n'
              'int h() {\n  return 2;\n}\n}  // namespace cosim\n')
    with tempfile.NamedTemporaryFile('w', suffix='.cpp', delete=False) as f:
        f.write(source)
    found = long_functions(pathlib.Path(f.name), MAX_RUN_FUNCTION_LINES)
    pathlib.Path(f.name).unlink()
    if found != [(5, 81)]:
        print(f'self-test: expected one 81-line function at line 5, found {found}')
        return 1
    return 0


def main():
    if sys.argv[1] == '--self-test':
        return self_test()
    root = pathlib.Path(sys.argv[1])
    problems = []
    for f in sorted((root / 'cli').glob('*.[ch]*')):
        count = len(f.read_text().split('\n')) - 1
        if count > MAX_CLI_FILE_LINES:
            problems.append(f'{f.relative_to(root)}: {count} lines (at most {MAX_CLI_FILE_LINES})')
    for f in sorted((root / 'run').glob('*.[ch]*')):
        for line, length in long_functions(f, MAX_RUN_FUNCTION_LINES):
            problems.append(f'{f.relative_to(root)}:{line}: a function of {length} lines '
                            f'(at most {MAX_RUN_FUNCTION_LINES})')
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
