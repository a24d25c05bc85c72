#!/usr/bin/env python3
"""Size figures of the C++ sources, tests aside: the largest files and the longest functions.

Usage: scripts/code_metrics.py [--top N] [--all]   (from the repository root)
A function's length counts the lines from its signature's first line to its closing brace.
--all includes tests/. The figures are what issue-style reviews quote: files over 600 lines,
functions over 80 lines.
"""
import argparse
import re
import subprocess

CONTROL = re.compile(r'\b(if|for|while|switch|catch|do|else|try)\s*(\(|$)')
SCOPE = re.compile(r'^\s*(namespace\b|class\b|struct\b|enum\b|union\b|extern\s+"C")')


def strip_code(text):
    """Blanks out comments, strings and character literals, keeping line breaks."""
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
            end = ')' + (m.group(1) if m else '') + '"'
            j = text.find(end, i)
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def functions(path):
    """(name, first line, last line) of every function body not nested in another."""
    code = strip_code(open(path, encoding='utf-8', errors='replace').read())
    found, stack, head_start = [], [], 0
    for i, c in enumerate(code):
        if c in ';}':
            if c == '}' and stack:
                kind, start, name = stack.pop()
                if kind == 'function':
                    found.append((name, code.count('\n', 0, start) + 1,
                                  code.count('\n', 0, i) + 1))
            head_start = i + 1
        elif c == '{':
            head = code[head_start:i]
            in_function = any(k == 'function' for k, _, _ in stack)
            kind = 'block'
            if not in_function and not SCOPE.match(head) and not head.rstrip().endswith('='):
                sig = ' '.join(head.split())
                if re.search(r'\)\s*(const|override|noexcept|final|mutable|->[^{]*|:[^{]*)*\s*$',
                             sig) and not CONTROL.match(sig):
                    kind = 'function'
            name = ''
            if kind == 'function':
                m = re.search(r'([~\w:<>]+)\s*\(', ' '.join(head.split()))
                name = m.group(1) if m else '?'
                first = len(head) - len(head.lstrip())
                start = head_start + first
            else:
                start = i
            stack.append((kind, start, name))
            head_start = i + 1
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--top', type=int, default=5)
    ap.add_argument('--all', action='store_true', help='include tests/')
    args = ap.parse_args()
    files = subprocess.check_output(['git', 'ls-files', '*.cc', '*.h']).decode().split()
    if not args.all:
        files = [f for f in files if not f.startswith('tests/')]
    sizes = sorted(((sum(1 for _ in open(f, errors='replace')), f) for f in files), reverse=True)
    funcs = sorted(((last - first + 1, f'{f}:{first}', name)
                    for f in files for name, first, last in functions(f)), reverse=True)
    print(f'files: {len(files)}, over 600 lines: {sum(1 for n, _ in sizes if n > 600)}, '
          f'functions over 80 lines: {sum(1 for n, _, _ in funcs if n > 80)}')
    print('largest files:')
    for n, f in sizes[:args.top]:
        print(f'  {n:5d}  {f}')
    print('longest functions:')
    for n, where, name in funcs[:args.top]:
        print(f'  {n:5d}  {where}  {name}')


if __name__ == '__main__':
    main()
