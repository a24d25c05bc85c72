#!/usr/bin/env python3
"""Checks the documentation against the code.

1. Every relative link in README.md, results/README.md, docs/*.md and docs/experiments/*.md
   names a file that exists, and every #anchor a heading of that file (GitHub's slugs).
2. Every block between `<!-- BEGIN GENERATED name -->` and `<!-- END GENERATED name -->` is what
   the program that owns the declaration prints for it (GENERATORS below), so a table that
   mirrors code cannot drift from it. `--fix` rewrites the blocks instead of failing.
3. Every page of docs/ is at most MAX_PAGE_LINES long: the pages are a reference, and dated runs
   and how a default was found go to the experiment log, one page per study (docs/experiments/).

Usage: check_docs.py BIN_DIR SOURCE_DIR [--fix]
"""
import glob
import os
import re
import subprocess
import sys

# name of a generated block -> the command (program in BIN_DIR, then its arguments).
GENERATORS = {
    'metrics': ['rlpos-sim', 'describe', 'metrics'],
    'track-metrics': ['rlpos-sim', 'describe', 'track-metrics'],
    'default-sets': ['rlpos-sim', 'describe', 'defaults'],
}
# settings-<section>: that section's settings table (rlpos-sim describe settings --section).
SETTINGS_PREFIX = 'settings-'
# The exit codes' one declaration: the ExitCode enum of rlpos-campaign. The docs' table explains
# each code at more length, so only its set of codes is checked against the enum.
EXIT_CODES_HEADER = 'coordinator/cli/campaign_commands.h'
EXIT_CODE = re.compile(r'^\s*kExit\w+\s*=\s*(\d+),', re.M)
BLOCK = re.compile(r'(<!-- BEGIN GENERATED ([\w.-]+) -->\n)(.*?)(<!-- END GENERATED \2 -->)', re.S)
LINK = re.compile(r'\[[^\]]*\]\(([^)\s]+)\)')
MAX_PAGE_LINES = 600


def slug(heading):
    text = re.sub(r'[`*_]|\[([^\]]*)\]\([^)]*\)', r'\1', heading.strip().lower())
    return re.sub(r'[^\w\- ]', '', text).replace(' ', '-')


def anchors(path):
    seen, out, fenced = {}, set(), False
    for line in open(path, encoding='utf-8'):
        if line.startswith('```'):
            fenced = not fenced
        m = re.match(r'(#{1,6})\s+(.*)', line)
        if m and not fenced:
            base = slug(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            out.add(base if n == 0 else f'{base}-{n}')
    return out


def check_links(pages, source_dir):
    errors = []
    for page in pages:
        text = re.sub(r'```.*?```', '', open(page, encoding='utf-8').read(), flags=re.S)
        for target in LINK.findall(text):
            if re.match(r'[a-z]+:', target):
                continue  # http(s), mailto: not ours to check
            file_part, _, anchor = target.partition('#')
            dest = os.path.normpath(os.path.join(os.path.dirname(page), file_part)) \
                if file_part else page
            rel = os.path.relpath(page, source_dir)
            if not os.path.exists(dest):
                errors.append(f'{rel}: link to {target}: no such file')
            elif anchor and dest.endswith('.md') and anchor not in anchors(dest):
                errors.append(f'{rel}: link to {target}: no heading #{anchor}')
    return errors


def check_lengths(pages, source_dir):
    errors = []
    for page in pages:
        rel = os.path.relpath(page, source_dir)
        count = sum(1 for _ in open(page, encoding='utf-8'))
        if rel.startswith('docs' + os.sep) and count > MAX_PAGE_LINES:
            errors.append(f'{rel}: {count} lines, more than {MAX_PAGE_LINES}: split it, or move '
                          'its dated runs to docs/experiments/')
    return errors


def generator(name):
    """The command that prints block `name`, or None."""
    if name.startswith(SETTINGS_PREFIX):  # one section's settings table
        return ['rlpos-sim', 'describe', 'settings', '--section', name[len(SETTINGS_PREFIX):]]
    return GENERATORS.get(name)


def generated(bin_dir, name):
    cmd = generator(name)
    run = subprocess.run([os.path.join(bin_dir, cmd[0])] + cmd[1:], capture_output=True,
                         text=True, timeout=60)
    if run.returncode != 0:
        raise RuntimeError(f'{" ".join(cmd)} exited {run.returncode}: {run.stderr.strip()}')
    return run.stdout


def check_exit_codes(rel, table, source_dir):
    header = open(os.path.join(source_dir, EXIT_CODES_HEADER), encoding='utf-8').read()
    declared = sorted(int(c) for c in EXIT_CODE.findall(header))
    documented = sorted(int(c) for c in re.findall(r'^\| (\d+) \|', table, re.M))
    if not declared:
        return [f'{EXIT_CODES_HEADER}: no exit codes found']
    if declared != documented:
        return [f'{rel}: exit codes {documented} differ from {EXIT_CODES_HEADER}: {declared}']
    return []


def check_blocks(pages, bin_dir, source_dir, fix):
    errors = []
    for page in pages:
        text = open(page, encoding='utf-8').read()
        rel = os.path.relpath(page, source_dir)

        def replace(m):
            name = m.group(2)
            if name == 'exit-codes':
                errors.extend(check_exit_codes(rel, m.group(3), source_dir))
                return m.group(0)
            if generator(name) is None:
                errors.append(f'{rel}: generated block "{name}" has no generator')
                return m.group(0)
            want = generated(bin_dir, name)
            if m.group(3) != want and not fix:
                errors.append(f'{rel}: block "{name}" differs from `{" ".join(generator(name))}`'
                              f' (run tests/docs/check_docs.py BIN_DIR . --fix)')
            return m.group(1) + want + m.group(4)

        new = BLOCK.sub(replace, text)
        if fix and new != text:
            open(page, 'w', encoding='utf-8').write(new)
            print(f'rewrote {rel}')
    return errors


def exit_with(errors, summary):
    """Each error on stderr, then the summary on stdout; exit status 1 if there was an error
    (check_layout.py ends so too)."""
    for e in errors:
        print(e, file=sys.stderr)
    print(summary)
    sys.exit(1 if errors else 0)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    bin_dir, source_dir = sys.argv[1], sys.argv[2]
    fix = '--fix' in sys.argv[3:]
    pages = [os.path.join(source_dir, p) for p in ('README.md', 'results/README.md')]
    pages += sorted(glob.glob(os.path.join(source_dir, 'docs', '*.md')))
    pages += sorted(glob.glob(os.path.join(source_dir, 'docs', 'experiments', '*.md')))
    errors = check_links(pages, source_dir) + check_blocks(pages, bin_dir, source_dir, fix)
    errors += check_lengths(pages, source_dir)
    exit_with(errors, f'{len(pages)} pages, {len(errors)} problems')


if __name__ == '__main__':
    main()
