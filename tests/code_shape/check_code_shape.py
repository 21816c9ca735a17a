#!/usr/bin/env python3
"""Checks the shape we keep the code in, so that it stays that way:
- every C++ source file (.cpp, .h) outside tests/ is at most 400 lines, and those of the
  command-line front end (cli/) at most 300;
- every function in those files is at most 80 lines;
- every C++ file under tests/ is at most 600 lines (test bodies are lists of cases and are not
  held to the function limit).

Functions are found by brace depth outside namespaces: a body opens where a '{' takes the depth
from 0 to 1 on a line that does not open a namespace, class, struct, enum or union, and closes
where the depth returns to 0; a '{' right after '=' opens a variable's initializer (a table of
data), which is not a function. Strings, character literals and comments are blanked first so their
braces do not count. Lambdas and local classes count towards the function that holds them.
Build folders (build*, out, b) and hidden folders are skipped.
Usage: check_code_shape.py SOURCE_DIR [FOLDER ...]   (exit 1 and one line per offence; FOLDERs,
relative to SOURCE_DIR, restrict the check to those folders)
       check_code_shape.py --self-test"""
import pathlib
import re
import sys

MAX_SOURCE_FILE_LINES = 400
MAX_CLI_FILE_LINES = 300
MAX_TEST_FILE_LINES = 600
MAX_FUNCTION_LINES = 80
SOURCE_SUFFIXES = ('.cpp', '.h')
SKIPPED_TOP_FOLDERS = ('out', 'b')
TYPE_OPENER = re.compile(r'^\s*(template\s*<.*>\s*)?(namespace|class|struct|enum|union)\b')
# `= {` opens the initializer of a variable (a table of data), not a function body.
INITIALIZER_OPENER = re.compile(r'(?<![=<>!])=\s*\{')


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
    # stack: 'scope' for a namespace/type brace, 'data' inside an initializer, 'code' otherwise
    found, stack, start = [], [], None
    for number, line in enumerate(lines, 1):
        for ch in line:
            if ch == '{':
                if start is not None or 'data' in stack:
                    stack.append(stack[-1] if start is None else 'code')
                elif TYPE_OPENER.match(line):
                    stack.append('scope')
                elif INITIALIZER_OPENER.search(line):
                    stack.append('data')
                else:
                    start = number  # a function body at namespace or class level
                    stack.append('code')
            elif ch == '}' and stack:
                stack.pop()
                if start is not None and all(kind == 'scope' for kind in stack):
                    if number - start + 1 > limit:
                        found.append((start, number - start + 1))
                    start = None
    return found


def source_files(root, folders):
    """Every C++ source file under `root` (or under its `folders`), build and hidden folders
    left out, in a stable order."""
    found = []
    for start in ([root / f for f in folders] if folders else [root]):
        for f in start.rglob('*'):
            parts = f.relative_to(root).parts
            top = parts[0]
            if (top.startswith('build') or top in SKIPPED_TOP_FOLDERS
                    or any(p.startswith('.') for p in parts)):
                continue
            if f.is_file() and f.suffix in SOURCE_SUFFIXES:
                found.append(f)
    return sorted(set(found))


def line_count(path):
    """Lines of `path` as an editor numbers them (a final newline does not open another)."""
    return len(path.read_text().split('\n')) - 1


def offences(root, folders=()):
    """One line per file or function of `root` (or of its `folders`) over its limit."""
    problems = []
    for f in source_files(root, folders):
        name = f.relative_to(root)
        is_test = name.parts[0] == 'tests'
        limit = (MAX_TEST_FILE_LINES if is_test else
                 MAX_CLI_FILE_LINES if name.parts[0] == 'cli' else MAX_SOURCE_FILE_LINES)
        count = line_count(f)
        if count > limit:
            problems.append(f'{name}: {count} lines (at most {limit})')
        if is_test:
            continue
        for line, length in long_functions(f, MAX_FUNCTION_LINES):
            problems.append(f'{name}:{line}: a function of {length} lines '
                            f'(at most {MAX_FUNCTION_LINES})')
    return problems


def self_test():
    """The checker itself: a namespace, a class and a lambda do not hide an 81-line function,
    braces in strings and comments do not count, a table of data is not a function; file limits are 400 lines for sources, 300 for
    cli/ and 600 for tests/, tests are not held to the function limit, build folders are skipped
    and FOLDER arguments restrict the check."""
    import tempfile
    body = '\n'.join(['  x += 1;  // }'] * 78)
    source = ('namespace cosim {\nstruct S {\n  int f() const { return 1; }\n};\n'
              'int g(int x) {\n  auto l = [] { return "{"; };\n' + body + '\n}\n'
              'int h() {\n  return 2;\n}\n}  // namespace cosim\n')
    with tempfile.TemporaryDirectory() as d:
        root = pathlib.Path(d)

        def write(name, text):
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)

        def lines(n):
            return 'int x;\n' * n

        write('sim/long_function.cpp', source)
        found = long_functions(root / 'sim/long_function.cpp', MAX_FUNCTION_LINES)
        if found != [(5, 81)]:
            print(f'self-test: expected one 81-line function at line 5, found {found}')
            return 1
        table = ('const int kTable[2][90] = {\n  {\n' + '    1,\n' * 90 + '  },\n  {1}};\n'
                 'bool same(int a, int b) {\n  return a == b;\n}\n')
        write('sim/table.cpp', table)
        if long_functions(root / 'sim/table.cpp', MAX_FUNCTION_LINES):
            print('self-test: a 92-line table of data was counted as a function')
            return 1
        write('sim/at_limit.h', lines(400))
        write('sim/over_limit.h', lines(401))
        write('cli/at_limit.cpp', lines(300))
        write('cli/over_limit.cpp', lines(301))
        write('tests/sim/at_limit_test.cpp', lines(600))
        write('tests/sim/over_limit_test.cpp', lines(601))
        write('tests/sim/long_test.cpp', source)
        write('build/generated.cpp', lines(1000))
        write('build-debug/generated.cpp', lines(1000))
        write('.cache/generated.h', lines(1000))
        write('docs/notes.txt', lines(1000))
        expected = ['cli/over_limit.cpp: 301 lines (at most 300)',
                    'sim/long_function.cpp:5: a function of 81 lines (at most 80)',
                    'sim/over_limit.h: 401 lines (at most 400)',
                    'tests/sim/over_limit_test.cpp: 601 lines (at most 600)']
        found = offences(root)
        if found != expected:
            print(f'self-test: expected {expected}, found {found}')
            return 1
        found = offences(root, ['cli'])
        if found != expected[:1]:
            print(f'self-test: restricted to cli/, expected {expected[:1]}, found {found}')
            return 1
    return 0


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    if sys.argv[1] == '--self-test':
        return self_test()
    root = pathlib.Path(sys.argv[1])
    folders = sys.argv[2:]
    for folder in folders:
        if not (root / folder).is_dir():
            print(f'{root / folder}: no such folder')
            return 2
    problems = offences(root, folders)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
