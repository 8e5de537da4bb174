"""The pass/fail count of the YADE test scripts: check(ok, label) prints
'yade LABEL' or 'FAIL yade LABEL'; summary() prints 'N passed, N failed' and
returns the exit status."""
counts = {'passed': 0, 'failed': 0}


def check(ok, label):
    counts['passed' if ok else 'failed'] += 1
    print('%syade %s' % ('' if ok else 'FAIL ', label))


def summary():
    print('%d passed, %d failed' % (counts['passed'], counts['failed']))
    return 1 if counts['failed'] else 0
