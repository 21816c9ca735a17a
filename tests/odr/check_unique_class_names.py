#!/usr/bin/env python3
"""Checks that no two classes or structs in different files share a qualified name.

Two definitions of cosim::AntGrid linked into one program break C++'s one-definition rule: the
behaviour is undefined, and inline members (or a vtable) of one may silently serve the other.
The compiler and the linker say nothing, so this script looks: it reads every header and source
file, follows namespaces, classes and other braces, and records each class or struct
definition at namespace or class scope by its qualified name. Forward declarations, classes in
anonymous namespaces (one per translation unit) and classes local to a function are not
definitions that can clash. Specialisations (name<...>) are not counted.
Usage: check_unique_class_names.py SOURCE_DIR   (exit 1 and one line per clash)
       check_unique_class_names.py --self-test"""
import pathlib
import re
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / 'code_shape'))
from check_code_shape import blank_literals_and_comments  # noqa: E402

SKIPPED_DIRS = {'.git', 'third_party'}
IDENT = r'[A-Za-z_]\w*'
# A namespace opening (named, nested a::b, or anonymous), a class or struct definition (name,
# maybe final, maybe a base list, then its body), or any other brace.
TOKEN = re.compile(
    r'(?P<ns>\bnamespace\s*(?P<ns_name>' + IDENT + r'(?:\s*::\s*(?:inline\s+)?' + IDENT +
    r')*)?\s*\{)'
    r'|(?P<cls>\b(?:class|struct)\s+(?:alignas\s*\([^)]*\)\s*)?(?:\[\[[^\]]*\]\]\s*)?'
    r'(?P<cls_name>' + IDENT + r')\s*(?:final\s*)?(?::(?!:)[^;{}()]*)?\{)'
    r'|(?P<open>\{)|(?P<close>\})')


def definitions(text):
    """(qualified name, line) of each class or struct defined at namespace or class scope."""
    text = blank_literals_and_comments(text)
    found, stack = [], []  # stack frames: ('ns', name), ('anon', ''), ('cls', name), ('other', '')
    for m in TOKEN.finditer(text):
        if m.group('ns'):
            name = m.group('ns_name')
            stack.append(('ns', re.sub(r'\s|inline', '', name)) if name else ('anon', ''))
        elif m.group('cls'):
            before = text[max(0, m.start() - 12):m.start()]
            if re.search(r'\benum\s+$', before):  # enum class X { ... }
                stack.append(('other', ''))
                continue
            name = m.group('cls_name')
            if all(kind in ('ns', 'cls') for kind, _ in stack):
                qualified = '::'.join([n for _, n in stack] + [name])
                found.append((qualified, text.count('\n', 0, m.start()) + 1))
            stack.append(('cls', name))
        elif m.group('open'):
            stack.append(('other', ''))
        elif stack:
            stack.pop()
    return found


def sources(root):
    for path in sorted(root.rglob('*')):
        parts = path.relative_to(root).parts
        if path.suffix not in ('.h', '.hpp', '.cpp', '.cc'):
            continue
        if any(p in SKIPPED_DIRS or p.startswith('build') for p in parts[:-1]):
            continue
        yield path


def clashes(root):
    where = {}
    for path in sources(root):
        for name, line in definitions(path.read_text(errors='replace')):
            where.setdefault(name, []).append((path.relative_to(root), line))
    out = []
    for name, places in sorted(where.items()):
        files = {p for p, _ in places}
        if len(files) > 1:
            out.append(name + ' is defined in ' +
                       ', '.join(f'{p}:{line}' for p, line in places) +
                       ': one name, two classes (rename one by what it is)')
    return out


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / 'a.h').write_text(
            'namespace cosim {\nclass Grid {\n public:\n  struct Cell { int x; };\n};\n'
            'class Forward;\nenum class Mode { A };\nnamespace {\nstruct Local {};\n}\n'
            'template <class T> struct Box { T v; };\n}  // namespace cosim\n')
        (root / 'b.h').write_text(
            '// class Grid { in a comment\nnamespace cosim {\nstruct Grid : public Base<int> {\n'
            '  int f() { struct Inside {}; return 0; }\n};\nstruct Forward;\n'
            'enum class Mode : int { B };\nnamespace {\nstruct Local {};\n}\n'
            'const char* s = "struct Box {";\n}\nnamespace other { class Grid {}; }\n'
            'namespace cosim::detail { struct Cell {}; }\n')
        (root / 'c.cpp').write_text('namespace cosim {\nstruct Inside {};\nstruct stat st {};\n}\n')
        got = clashes(root)
        expected = ['cosim::Grid is defined in a.h:2, b.h:3: one name, two classes '
                    '(rename one by what it is)']
        if got != expected:
            print('self-test failed:\n  got      ' + repr(got) + '\n  expected ' + repr(expected))
            return 1
        names = sorted(n for n, _ in definitions((root / 'a.h').read_text()))
        if names != ['cosim::Box', 'cosim::Grid', 'cosim::Grid::Cell']:
            print('self-test failed: definitions of a.h: ' + repr(names))
            return 1
    print('self-test passed')
    return 0


def main(argv):
    if len(argv) == 2 and argv[1] == '--self-test':
        return self_test()
    if len(argv) != 2:
        print(__doc__)
        return 2
    found = clashes(pathlib.Path(argv[1]))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
