"""The Python side of servo_bc (yade_adapter/servo_bc_core.py, the C API's module, and servo_bc.py, the YADE
engine) for pip, with Debian's own setuptools and no network:

    make install PREFIX=/opt/servo_bc
    SERVO_BC_PREFIX=/opt/servo_bc python3 -m pip install --no-build-isolation .

The library is found where `make install` put it: SERVO_BC_PREFIX, else pkg-config's libdir of servo_bc, else
/usr/local (written into servo_bc_paths.py at build time)."""
import os
import re
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(HERE, 'build', 'python'), exist_ok=True)   # setup.cfg's build and egg_info base


def version():
    with open(os.path.join(HERE, 'src_core', 'include', 'sbc', 'version.h')) as f:
        return re.search(r'#define SBC_VERSION "([^"]+)"', f.read()).group(1)


def libdir():
    prefix = os.environ.get('SERVO_BC_PREFIX')
    if prefix:
        return os.path.join(os.path.abspath(prefix), 'lib')
    try:
        found = subprocess.run(['pkg-config', '--variable=libdir', 'servo_bc'], capture_output=True, text=True)
        if found.returncode == 0 and found.stdout.strip():
            return found.stdout.strip()
    except OSError:
        pass
    return '/usr/local/lib'


class BuildWithPaths(build_py):
    """build_py, and servo_bc_paths.py naming the library's folder."""

    def run(self):
        super().run()
        path = os.path.join(self.build_lib, 'servo_bc_paths.py')
        with open(path, 'w') as f:
            f.write('"""Where the servo_bc library was installed (servo_bc_core.py reads it)."""\nLIBDIR = %r\n'
                    % libdir())


setup(name='servo_bc', version=version(),
      description='Boundary conditions on particle aggregates (DEM): the C API module and the YADE engine',
      package_dir={'': 'yade_adapter'}, py_modules=['servo_bc_core', 'servo_bc', 'servo_bc_bonds'],
      cmdclass={'build_py': BuildWithPaths}, python_requires='>=3.7')
