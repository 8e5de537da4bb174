"""The docs against the behaviour (make check): every fenced block of README.md and docs/**/*.md that a marker
line just above it names is checked, so that a page cannot drift from what the code does.

    <!-- docs-check: file PATH -->     the block is the file PATH of the repository (comments and blank lines of
                                        both dropped, spaces squeezed)
    <!-- docs-check: prints COMMAND --> COMMAND, run by bash in a scratch folder holding build/, inputs/ and
                                        tests/ of the repository, prints every line of the block (each a line of
                                        its output, or the start of one)
Prints one line per block and "N passed, N failed". Usage: docs_check.py [ROOT]"""
import glob
import os
import re
import subprocess
import sys
import tempfile

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
MARKER = re.compile(r'^<!-- docs-check: (file|prints) (.+?) -->\s*$')
passed = failed = 0


def squeezed(lines):
    out = []
    for line in lines:
        line = ' '.join(line.split('#', 1)[0].split())
        if line:
            out.append(line)
    return out


def blocks(path):
    """(line number, kind, argument, block lines) of each marked block of the page"""
    lines = open(path, encoding='utf-8').read().split('\n')
    for k, line in enumerate(lines):
        m = MARKER.match(line)
        if not m:
            continue
        if k + 1 >= len(lines) or not lines[k + 1].startswith('```'):
            yield k + 1, 'broken', m.group(2), []
            continue
        end = k + 2
        while end < len(lines) and not lines[end].startswith('```'):
            end += 1
        yield k + 1, m.group(1), m.group(2), lines[k + 2:end]


def report(ok, text):
    global passed, failed
    if ok:
        passed += 1
        print('docs check: ' + text)
    else:
        failed += 1
        print('FAIL docs check: ' + text)


pages = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '**', '*.md'), recursive=True))
with tempfile.TemporaryDirectory() as scratch:
    for name in ('build', 'inputs', 'tests'):
        os.symlink(os.path.join(root, name), os.path.join(scratch, name))
    for page in pages:
        where = os.path.relpath(page, root)
        for number, kind, arg, block in blocks(page):
            label = '%s:%d' % (where, number)
            if kind == 'broken':
                report(False, '%s: a marker without a fenced block after it' % label)
            elif kind == 'file':
                try:
                    want = squeezed(open(os.path.join(root, arg), encoding='utf-8').read().split('\n'))
                except OSError as e:
                    report(False, '%s: %s' % (label, e))
                    continue
                got = squeezed(block)
                diff = [(a, b) for a, b in zip(got, want) if a != b]
                report(got == want, '%s: the block is %s%s' % (
                    label, arg, '' if got == want else ' (first difference: page %r, file %r; %d against %d lines)'
                    % (diff[0] if diff else ('', '')) + (len(got), len(want))))
            else:
                run = subprocess.run(['bash', '-c', arg], cwd=scratch, capture_output=True, text=True, timeout=600)
                out = [line.rstrip() for line in (run.stdout + run.stderr).split('\n')]
                missing = [line for line in block if line.strip() and
                           not any(o.startswith(line.rstrip()) for o in out)]
                report(not missing, '%s: `%s` prints the %d quoted lines%s' % (
                    label, arg, len([b for b in block if b.strip()]),
                    '' if not missing else '; not printed: %r (it printed %r)' % (missing[0][:120], out[-2:])))
print('%d passed, %d failed' % (passed, failed))
sys.exit(failed > 0)
