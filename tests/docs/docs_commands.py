#!/usr/bin/env python3
"""Runs the commands the docs show, as a new user pastes them, from the repository root.

The blocks run are the README's main command and its quick start, and each docs page's opening
block (its first ```sh block). Every command runs as written, through bash, in a copy of the
repository root: symlinks to the checkout, `build` to the build folder, and `results/` one folder
that the README's main command fills (e2e.mini_campaign runs it, as docs/tests.md's table says)
and the pages that read results share after it (CTest's fixture docs_results). Two changes: `/tmp/` is the page's own scratch folder and `HOME` another one, so that a
run leaves nothing in the checkout and two pages never share a file. A command that takes minutes
runs in the short form that docs/tests.md's table "The docs' commands" declares (that table is
read here: a row whose text is no longer in its page fails too).

A command fails the page when it exits non-zero or when its output loses its shape: `--json`
prints one JSON object, a file it writes with `--out FILE` or `> FILE` is there and not empty, a
.json of them parses, a .png is a PNG, an .svg an SVG.

Usage: docs_commands.py BUILD_DIR SOURCE_DIR WORK_DIR PAGE    (PAGE: README.md, docs/agents.md, ...)
(tests/docs/CMakeLists.txt registers a test per page that has an opening block.)
"""
import json
import os
import re
import shlex
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request

SHORT_FORMS_PAGE = 'docs/tests.md'
SHORT_FORMS_HEADING = "## The docs' commands"
NOT_RUN = '(not run)'
COMMAND_TIMEOUT_S = 900
SERVE_DEADLINE_S = 60
FENCE = re.compile(r'^```sh\n(.*?)^```', re.M | re.S)


def fail(page, message):
    sys.exit(f'{page}: {message}')


def blocks_of(source_dir, page):
    """The blocks of PAGE that run, each as (first line number, text)."""
    text = open(os.path.join(source_dir, page), encoding='utf-8').read()
    fences = list(FENCE.finditer(text))
    if not fences:
        fail(page, 'no ```sh block')
    chosen = [fences[0]]
    if page == 'README.md':
        quick = text.find('\n## Quick start\n')
        after = [f for f in fences if f.start() > quick] if quick >= 0 else []
        if not after:
            fail(page, 'no ```sh block under "## Quick start"')
        chosen.append(after[0])
    return [(text.count('\n', 0, f.start(1)) + 1, f.group(1)) for f in chosen]


def commands_of(first_line, block):
    """The block's commands (continuations joined, comments and blank lines dropped)."""
    out, current, start = [], '', first_line
    for number, line in enumerate(block.splitlines(), first_line):
        if not current and (not line.strip() or line.lstrip().startswith('#')):
            continue
        if not current:
            start = number
        if line.endswith('\\'):
            current += line[:-1]
            continue
        out.append((start, current + line))
        current = ''
    return out


def short_forms(source_dir):
    """docs/tests.md's table: (page, as written, runs as) for every row."""
    text = open(os.path.join(source_dir, SHORT_FORMS_PAGE), encoding='utf-8').read()
    at = text.find('\n' + SHORT_FORMS_HEADING + '\n')
    if at < 0:
        fail(SHORT_FORMS_PAGE, f'no heading "{SHORT_FORMS_HEADING}"')
    rows = []
    for line in text[at + 1:].split('\n## ')[0].splitlines():
        cells = [c.strip() for c in line.strip().strip('|').split('|')] if line.startswith('|') \
            else []
        if len(cells) < 4 or cells[0] in ('page', '') or set(cells[0]) <= set('-'):
            continue
        page, written, runs_as = (c.strip('`') for c in cells[:3])
        rows.append((page, written, runs_as))
    if not rows:
        fail(SHORT_FORMS_PAGE, f'no rows under "{SHORT_FORMS_HEADING}"')
    return rows


def mirror_root(source_dir, build_dir, scratch, results):
    """The repository root as the docs see it: the checkout, `build` and a shared `results/`."""
    root = os.path.join(scratch, 'root')
    os.makedirs(root)
    for name in os.listdir(source_dir):
        if name not in ('build', 'results') and not name.startswith('build-'):
            os.symlink(os.path.join(source_dir, name), os.path.join(root, name))
    os.symlink(os.path.abspath(build_dir), os.path.join(root, 'build'))
    os.symlink(results, os.path.join(root, 'results'))
    return root


def written_files(command, cwd):
    """The files a command says it writes: --out FILE (not a folder) and > FILE."""
    try:
        words = shlex.split(command)
    except ValueError:
        return []
    files = [words[i + 1] for i, w in enumerate(words[:-1]) if w in ('--out', '>')]
    return [os.path.join(cwd, f) for f in files if os.path.splitext(f)[1]]


def check_shape(command, stdout, cwd):
    """What a command's output must look like; an empty list when it does."""
    problems = []
    if '--json' in command.split() and '>' not in command.split():
        try:
            if not isinstance(json.loads(stdout), dict):
                problems.append('--json printed JSON that is not an object')
        except ValueError as error:
            problems.append(f'--json printed no JSON ({error})')
    for path in written_files(command, cwd):
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            problems.append(f'{path}: not written')
            continue
        head = open(path, 'rb').read(256)
        if path.endswith('.json'):
            try:
                json.load(open(path, encoding='utf-8'))
            except ValueError as error:
                problems.append(f'{path}: not JSON ({error})')
        elif path.endswith('.png') and not head.startswith(b'\x89PNG\r\n\x1a\n'):
            problems.append(f'{path}: not a PNG')
        elif path.endswith('.svg') and b'<svg' not in head:
            problems.append(f'{path}: not an SVG')
    return problems


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def run_server(command, cwd, env):
    """`rlpos-campaign serve`: up, its page answers, then stopped. Returns (rc, output)."""
    port = free_port()
    command = f'{command} --listen 127.0.0.1:{port}'
    server = subprocess.Popen(['bash', '-c', f'exec {command}'], cwd=cwd, env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.monotonic() + SERVE_DEADLINE_S
    try:
        while True:
            try:
                with urllib.request.urlopen(f'http://127.0.0.1:{port}/', timeout=5) as reply:
                    page = reply.read().decode('utf-8', 'replace')
                return (0, '') if '<html' in page.lower() else (1, 'GET / gave no HTML page')
            except OSError as error:
                if server.poll() is not None or time.monotonic() > deadline:
                    return 1, f'GET http://127.0.0.1:{port}/: {error}'
                time.sleep(0.2)
    finally:
        server.send_signal(signal.SIGTERM)
        output = server.communicate(timeout=30)[0]
        if server.returncode not in (0, -signal.SIGTERM):
            print(output, file=sys.stderr)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    build_dir, source_dir, work_dir, page = sys.argv[1:]
    source_dir, work_dir = os.path.abspath(source_dir), os.path.abspath(work_dir)
    forms = short_forms(source_dir)
    # Filled by the README's main command (e2e.mini_campaign) for the pages that read it.
    results = os.path.join(work_dir, 'results')
    os.makedirs(results, exist_ok=True)
    scratch = os.path.join(work_dir, page.replace('/', '_'))
    shutil.rmtree(scratch, ignore_errors=True)
    root = mirror_root(source_dir, build_dir, scratch, results)
    os.makedirs(os.path.join(scratch, 'tmp'))
    os.makedirs(os.path.join(scratch, 'home'))
    env = {k: v for k, v in os.environ.items() if not k.startswith('PYTHON')}
    env['HOME'] = os.path.join(scratch, 'home')

    mine = [(w, r) for p, w, r in forms if p == page]
    used = set()
    ran = 0
    for first_line, block in blocks_of(source_dir, page):
        for line, written in commands_of(first_line, block):
            command = written
            for as_written, runs_as in mine:
                if as_written in command:
                    used.add(as_written)
                    command = None if runs_as == NOT_RUN else command.replace(as_written, runs_as)
                    if command is None:
                        break
            if command is None:
                print(f'{page}:{line}: not run (docs/tests.md): {written}')
                continue
            command = command.replace('/tmp/', scratch + '/tmp/')
            started = time.monotonic()
            if re.search(r'rlpos-campaign serve\b', command):
                rc, stdout = run_server(command, root, env)
                stderr = ''
            else:
                run = subprocess.run(['bash', '-c', 'set -o pipefail; ' + command], cwd=root,
                                     env=env, capture_output=True, text=True,
                                     timeout=COMMAND_TIMEOUT_S)
                rc, stdout, stderr = run.returncode, run.stdout, run.stderr
            seconds = time.monotonic() - started
            problems = [f'exit {rc}'] if rc != 0 else check_shape(command, stdout, root)
            print(f'{page}:{line}: {seconds:.1f} s: {written}')
            if problems:
                tail = '\n'.join((stdout + stderr).strip().splitlines()[-20:])
                fail(page, f'line {line}: {"; ".join(problems)}\n$ {command}\n{tail}')
            ran += 1
    unused = [w for w, _ in mine if w not in used]
    if unused:
        fail(page, f'{SHORT_FORMS_PAGE} has a short form for text no longer here: {unused[0]}')
    print(f'{page}: {ran} commands ran as the docs show them')


if __name__ == '__main__':
    main()
