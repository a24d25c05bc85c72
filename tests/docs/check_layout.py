#!/usr/bin/env python3
"""The layout table of docs/architecture.md and the README's layout against the tree.

usage: check_layout.py SOURCE_DIR

- every folder of common/, idl/, worker/ and coordinator/ whose CMakeLists.txt builds something
  builds exactly one target (one folder, one library), and has the table's row with that target;
- every row of the table names such a folder and its target;
- the README's layout names every folder directly under common/, idl/, worker/ and coordinator/,
  and every folder it names (`name/`) exists.
"""
import os
import re
import sys

from check_docs import exit_with

TOPS = ('common', 'idl', 'worker', 'coordinator')
# The calls that make a target, and the target's name as their first argument.
TARGET_CALL = re.compile(
    r'^\s*(?:rlpos_library|rlpos_program|pybind11_add_module|idlc_generate)\(\s*(?:TARGET\s+)?'
    r'([A-Za-z0-9_-]+)', re.M)


def tree_targets(source_dir):
    found, errors = {}, []
    for top in TOPS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(source_dir, top)):
            dirnames.sort()
            if 'CMakeLists.txt' not in filenames:
                continue
            rel = os.path.relpath(dirpath, source_dir)
            text = open(os.path.join(dirpath, 'CMakeLists.txt'), encoding='utf-8').read()
            targets = TARGET_CALL.findall(text)
            if len(targets) > 1:
                errors.append(f'{rel}/CMakeLists.txt: builds {len(targets)} targets '
                              f'({", ".join(targets)}): one folder, one library')
            if targets:
                found[rel] = targets[0]
    return found, errors


def table_rows(architecture):
    rows = {}
    for line in open(architecture, encoding='utf-8'):
        m = re.match(r'^\| `([a-z_/]+)/?` \| `([A-Za-z0-9_-]+)` \|', line)
        if m:
            rows[m.group(1)] = m.group(2)
    return rows


def readme_layout(readme):
    text = open(readme, encoding='utf-8').read()
    m = re.search(r'^## Layout\n+```\n(.*?)^```', text, re.M | re.S)
    if not m:
        return None
    entries, top = {}, None
    for line in m.group(1).splitlines():
        head = re.match(r'^([A-Za-z0-9_.-]+/?)\s', line + ' ')
        if head and not line.startswith(' '):
            top = head.group(1).rstrip('/')
            entries[top] = line[len(head.group(1)):]
        elif top:
            entries[top] += ' ' + line
    return entries


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    source_dir = sys.argv[1]
    found, errors = tree_targets(source_dir)
    rows = table_rows(os.path.join(source_dir, 'docs', 'architecture.md'))
    for folder, target in sorted(found.items()):
        if folder not in rows:
            errors.append(f'docs/architecture.md: no row for {folder} ({target})')
        elif rows[folder] != target:
            errors.append(f'docs/architecture.md: {folder} builds {target}, the table says '
                          f'{rows[folder]}')
    for folder in sorted(set(rows) - set(found)):
        errors.append(f'docs/architecture.md: row {folder} ({rows[folder]}) names no folder that '
                      'builds a target')
    layout = readme_layout(os.path.join(source_dir, 'README.md'))
    if layout is None:
        errors.append('README.md: no "## Layout" section with a code block')
        layout = {}
    for top in TOPS:
        named = set(re.findall(r'(?<![A-Za-z0-9_./-])([a-z_]+)/', layout.get(top, '')))
        for sub in sorted(os.listdir(os.path.join(source_dir, top))):
            if os.path.isdir(os.path.join(source_dir, top, sub)) and sub not in named:
                errors.append(f'README.md: the layout does not name {top}/{sub}/')
    for top, entry in sorted(layout.items()):
        for path in re.findall(r'(?<![A-Za-z0-9_./-])((?:[a-z_]+/)+)', entry):
            base = os.path.join(source_dir, top) if os.path.isdir(os.path.join(source_dir, top)) \
                else source_dir
            nested = [os.path.join(base, path), os.path.join(source_dir, path)]
            nested += [os.path.join(base, sub, path) for sub in os.listdir(base)
                       if os.path.isdir(os.path.join(base, sub))]
            if not any(os.path.isdir(p) for p in nested):
                errors.append(f'README.md: the layout of {top}/ names {path}, which is no folder')
    exit_with(errors,
              f'{len(found)} folders with a target, {len(rows)} table rows, {len(errors)} problems')


if __name__ == '__main__':
    main()
