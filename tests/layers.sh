#!/usr/bin/env bash
# The core's layers go one way (docs/core.md, "Layers"): base -> servo ->
# engines -> io -> host -> runner. From the symbols of the compiled objects
# (nm): no file calls a function or reads data defined in a later layer, and
# no files call each other round in a cycle. Prints every violation and
# "N passed, N failed".
# Usage: layers.sh BUILD
set -u
B=$(cd "${1:-build}" && pwd)
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 1
python3 - "$B" src_core/src/*/*.c <<'PY'
import subprocess, sys
order = ['base', 'servo', 'engines', 'io', 'host', 'runner']
build, sources = sys.argv[1], sys.argv[2:]
defined, wanted = {}, {}
for src in sources:
    name = src[len('src_core/src/'):-2]                       # layer/file
    out = subprocess.run(['nm', '%s/core/%s.o' % (build, name)], capture_output=True, text=True, check=True).stdout
    defined[name] = {l.split()[2] for l in out.splitlines() if len(l.split()) == 3 and l.split()[1] in 'TDRBC'}
    wanted[name] = {l.split()[1] for l in out.splitlines() if len(l.split()) == 2 and l.split()[0] == 'U'}
owner = {s: n for n, d in defined.items() for s in d}
calls = {n: sorted({owner[s] for s in wanted[n] if s in owner and owner[s] != n}) for n in defined}
passed = failed = 0
for n in sorted(calls):
    layer = n.split('/')[0]
    if layer not in order:
        failed += 1
        print('FAIL layers: %s is in no layer (%s)' % (n, ' -> '.join(order)))
        continue
    up = [t for t in calls[n] if order.index(t.split('/')[0]) > order.index(layer)]
    for t in up:
        failed += 1
        syms = sorted(s for s in wanted[n] if owner.get(s) == t)
        print('FAIL layers: %s calls %s, a later layer (%s)' % (n, t, ', '.join(syms[:4])))
    if not up:
        passed += 1
# cycles: strongly connected components of the call graph (Tarjan)
index, low, stack, on, cycles = {}, {}, [], set(), []
def visit(v, counter=[0]):
    index[v] = low[v] = counter[0]; counter[0] += 1; stack.append(v); on.add(v)
    for w in calls[v]:
        if w not in index:
            visit(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v:
                break
        if len(comp) > 1:
            cycles.append(sorted(comp))
sys.setrecursionlimit(10000)
for v in sorted(calls):
    if v not in index:
        visit(v)
for c in cycles:
    failed += 1
    print('FAIL layers: files that call each other round: %s' % ', '.join(c))
if not cycles:
    passed += 1
    print('layers: %d files, %d calls between files, every one to the same or an earlier layer, no cycle'
          % (len(calls), sum(len(c) for c in calls.values())))
print('%d passed, %d failed' % (passed, failed))
sys.exit(failed > 0)
PY
