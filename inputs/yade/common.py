"""Shared by the YADE input scripts: the servo_bc module on the path, and packings
written by the embedded runner (build/servo-bc), so that YADE loads the very file
every other host loads."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
sys.path.insert(0, os.path.join(ROOT, 'yade_adapter'))
import servo_bc  # noqa: E402  (after the path)


def runner_packing(lines, path):
    """Runs the runner on `lines` (its script grammar) followed by `write_packing yade path`."""
    runner = os.path.join(ROOT, 'build', 'servo-bc')
    with tempfile.NamedTemporaryFile('w', suffix='.sbc', delete=False) as f:
        f.write('\n'.join(lines + ['write_packing yade %s' % os.path.abspath(path)]) + '\n')
    try:
        done = subprocess.run([runner, f.name], capture_output=True, text=True)
    finally:
        os.unlink(f.name)
    if done.returncode != 0:
        raise servo_bc.ServoBCError('servo-bc: ' + (done.stderr or done.stdout).strip())
    return path


def args(usage, count):
    """The script's arguments after `yade -n -x SCRIPT`."""
    if len(sys.argv) - 1 < count:
        sys.exit('usage: yade -n -x %s %s' % (sys.argv[0], usage))
    return sys.argv[1:]
