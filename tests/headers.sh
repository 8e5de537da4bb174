#!/usr/bin/env bash
# Every public header (src_core/include/sbc/*.h, the host-facing ones, and
# sbc/embedded/*.h, the embedded engines' and runner's) can be included from C++
# without a wrapper: after its include guard and includes, an extern "C" block
# that opens before its first declaration and closes before the guard's
# #endif (tests/cxx_headers.cpp links a few of them from C++). Prints
# "N passed, N failed".
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
python3 - "$top"/src_core/include/sbc/*.h "$top"/src_core/include/sbc/embedded/*.h <<'PY'
import re, sys
passed = failed = 0
for path in sys.argv[1:]:
    text = re.sub(r'/\*.*?\*/', lambda m: '\n' * m.group(0).count('\n'), open(path).read(), flags=re.S)
    lines = text.split('\n')
    opening = [i for i, l in enumerate(lines) if l.strip() == 'extern "C" {']
    code = [i for i, l in enumerate(lines) if l.strip() and not l.startswith('#') and l.strip() not in ('extern "C" {', '}')]
    closing = [i for i, l in enumerate(lines) if l.strip() == '}' and i > (opening[0] if opening else 0)]
    name = path.split('/src_core/')[-1]
    if len(opening) == 1 and code and opening[0] < code[0] and closing and closing[-1] > code[-1]:
        passed += 1
        print('header %s: extern "C" around all %d lines of declarations' % (name, len(code)))
    else:
        failed += 1
        print('FAIL header %s: no extern "C" block around every declaration' % name)
print('%d passed, %d failed' % (passed, failed))
sys.exit(failed > 0)
PY
