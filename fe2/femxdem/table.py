"""The side-by-side table of fe2/femxdem/run.sh: OUT/femxdem.csv and OUT/servo_bc.csv as one Markdown table
(OUT/side_by_side.md, printed), and the two force paths as OUT/side_by_side.svg when build/servo-bc-plot exists.
Usage: table.py OUT [PLOT]"""
import csv
import os
import subprocess
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    out = sys.argv[1]
    plot = sys.argv[2] if len(sys.argv) > 2 else 'build/servo-bc-plot'
    fx, sb = rows(os.path.join(out, 'femxdem.csv')), rows(os.path.join(out, 'servo_bc.csv'))
    lines = ['| step | u (mm) | force FEMxDEM (N/m) | force servo_bc (N/m) | servo_bc / FEMxDEM − 1 | macro iterations '
             'FEMxDEM / servo_bc | CPU per Gauss point FEMxDEM / servo_bc (s) | CPU ratio | RVE unbalanced FEMxDEM '
             '(mean / largest) | servo_bc points uncertified | servo_bc macro residual |',
             '| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |']
    for a, b in zip(fx, sb):
        fa, fb = float(a['force']), float(b['force'])
        ca, cb = float(a['cpu_per_point']), float(b['cpu_per_point'])
        lines.append('| %s | %.2f | %.1f | %.1f | %+.2f %% | %s / %s | %.3f / %.3f | %.2f | %.2g / %.2g | %s | %s |'
                     % (a['step'], 1e3 * float(a['u']), fa, fb, 100 * (fb / fa - 1), a['iterations'],
                        b['iterations'], ca, cb, cb / ca, float(a['unbalanced_mean_max']),
                        float(a['unbalanced_largest_max']), b['uncertified'], b['residual']))
    lines.append('')
    lines.append('Stored state per Gauss point: FEMxDEM %s bytes (its pickled YADE scene), servo_bc %s bytes '
                 '(MaterialPoint.state()).' % (fx[-1]['rve_bytes'], sb[-1]['point_bytes']))
    text = '\n'.join(lines) + '\n'
    with open(os.path.join(out, 'side_by_side.md'), 'w') as f:
        f.write(text)
    print(text, end='')
    if os.path.exists(plot):
        subprocess.run([plot, os.path.join(out, 'side_by_side.svg'),
                        "FEMxDEM's biaxial example shrunk, and servo_bc on its RVE", 'platen displacement u (mm)',
                        'force on the platen (N/m of thickness)', 'u', '1e3', 'force', '1',
                        os.path.join(out, 'femxdem.csv'), 'FEMxDEM', os.path.join(out, 'servo_bc.csv'),
                        'servo_bc (P), interior newton'], check=True)


if __name__ == '__main__':
    main()
