"""The aggregate's size against the DNS (docs/fe2.md, "The aggregate's size"): fe2/biaxial.py at n0 = 25, 100, 400
discs per point, each on several specimens (--specimen S: every packing seed shifted by 10000 S, the DNS's too),
and the error of FE^2 against the DNS of the same specimen at the last platen displacement, in the force gained
under u and in the total force:

    gain error  = (F_K(u) - F_K(0)) / (F_DNS(u) - F_DNS(0)) - 1        total error = F_K(u) / F_DNS(u) - 1

Writes OUT/size_study.csv (n0,specimen,bc,gain,gain_DNS,gain_error,total,total_DNS,total_error; one row per path
that reached the last u), OUT/size_gain.svg and OUT/size_total.svg (the mean error of each condition against n0,
and its smallest and largest over the specimens, each a curve), prints the table of means and spreads, and keeps each run in
OUT/n{n0}_s{specimen}/. A path that stops is reported and left out of the means. Usage:
  python3 fe2/size_study.py [--n0s '25 100 400'] [--specimens 3] [--only D,P,T] [--steps 4]
                            [--out out/fe2/size] [--runner build/servo-bc] [--plot build/servo-bc-plot]
                            [--threads 2]"""
import argparse
import csv
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run_specimen(args, n0, specimen):
    """biaxial.py on one specimen: {K: [forces]} of the curves that reached the last u, and the wall time."""
    out = os.path.join(args.out, 'n%d_s%d' % (n0, specimen))
    t0 = time.time()
    done = subprocess.run([sys.executable, os.path.join(HERE, 'biaxial.py'), '--n0', str(n0), '--specimen',
                           str(specimen), '--steps', str(args.steps), '--only', args.only + ',DNS', '--out', out,
                           '--runner', args.runner, '--plot', args.plot, '--threads', str(args.threads)],
                          capture_output=True, text=True)
    with open(os.path.join(out, 'log'), 'w') as f:
        f.write(done.stdout + done.stderr)
    if done.returncode:
        print('fe2 size: n0 %d specimen %d: %s' % (n0, specimen, (done.stderr or done.stdout).strip()[-300:]),
              flush=True)
    rows = list(csv.DictReader(open(os.path.join(out, 'biaxial.csv'))))
    curves = {}
    for key in rows[0]:
        if key.startswith('force_') and all(row[key] for row in rows):
            curves[key[len('force_'):]] = [float(row[key]) for row in rows]
    return curves, time.time() - t0


def spread(values):
    return sum(values) / len(values), min(values), max(values)


def main():
    a = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    a.add_argument('--n0s', default='25 100 400')
    a.add_argument('--specimens', type=int, default=3)
    a.add_argument('--only', default='D,P,T')
    a.add_argument('--steps', type=int, default=4)
    a.add_argument('--out', default='out/fe2/size')
    a.add_argument('--runner', default='build/servo-bc')
    a.add_argument('--plot', default='build/servo-bc-plot')
    a.add_argument('--threads', type=int, default=2)
    args = a.parse_args()
    os.makedirs(args.out, exist_ok=True)
    n0s = [int(v) for v in args.n0s.split()]
    bcs = args.only.split(',')
    table = []
    for n0 in n0s:
        for specimen in range(args.specimens):
            curves, wall = run_specimen(args, n0, specimen)
            if 'DNS' not in curves:
                print('fe2 size: n0 %d specimen %d: the DNS stopped; the specimen is left out' % (n0, specimen))
                continue
            dns = curves['DNS']
            for bc in bcs:
                if bc not in curves:
                    print('fe2 size: n0 %d specimen %d: the (%s) path stopped; left out' % (n0, specimen, bc))
                    continue
                f = curves[bc]
                gain, gain_dns = f[-1] - f[0], dns[-1] - dns[0]
                table.append(dict(n0=n0, specimen=specimen, bc=bc, gain=gain, gain_DNS=gain_dns,
                                  gain_error=gain / gain_dns - 1.0, total=f[-1], total_DNS=dns[-1],
                                  total_error=f[-1] / dns[-1] - 1.0))
            print('fe2 size: n0 %d specimen %d done in %.0f s' % (n0, specimen, wall), flush=True)
    keys = ['n0', 'specimen', 'bc', 'gain', 'gain_DNS', 'gain_error', 'total', 'total_DNS', 'total_error']
    with open(os.path.join(args.out, 'size_study.csv'), 'w') as f:
        f.write(','.join(keys) + '\n')
        for row in table:
            f.write(','.join(str(row[k]) if k in ('n0', 'specimen', 'bc') else '%.17g' % row[k] for k in keys) + '\n')
    print('%-4s %6s %9s %28s %28s' % ('BC', 'n0', 'specimens', 'gain error: mean (min, max)',
                                       'total error: mean (min, max)'))
    for measure in ('gain_error', 'total_error'):
        files = []
        for bc in bcs:
            rows = [(n0,) + spread(v) for n0 in n0s
                    for v in [[r[measure] for r in table if r['bc'] == bc and r['n0'] == n0]] if v]
            for column, stat in ((1, 'mean'), (2, 'smallest'), (3, 'largest')):
                path = os.path.join(args.out, '%s_%s_%s.csv' % (measure, bc, stat))
                with open(path, 'w') as f:
                    f.write('n0,error\n' + ''.join('%d,%.17g\n' % (r[0], r[column]) for r in rows))
                files += [path, '(%s) %s' % (bc, stat)]
        if os.path.exists(args.plot) and table:
            subprocess.run([args.plot, os.path.join(args.out, 'size_%s.svg' % measure.split('_')[0]),
                            'FE2 against the DNS: %s' % measure.replace('_', ' '), 'discs per point n0',
                            'relative error (%)', 'n0', '1', 'error', '100'] + files, check=True)
    for bc in bcs:
        for n0 in n0s:
            g = [r['gain_error'] for r in table if r['bc'] == bc and r['n0'] == n0]
            t = [r['total_error'] for r in table if r['bc'] == bc and r['n0'] == n0]
            if g:
                print('%-4s %6d %9d %28s %28s' % ('(%s)' % bc, n0, len(g), '%+.3f (%+.3f, %+.3f)' % spread(g),
                                                   '%+.3f (%+.3f, %+.3f)' % spread(t)))
    print('fe2 size: wrote %s' % os.path.join(args.out, 'size_study.csv'))


if __name__ == '__main__':
    main()
