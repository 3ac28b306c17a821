#!/usr/bin/env python3
"""Drop statistics of the shear-stress signal of S3 stick-slip runs (docs/s3-bonded.md).

Why it exists: S3 eq. (9) with k_phi = 0 drops a contact's friction to zero at every slip
(the saw-tooth of tests/dem/StickSlipShearTest.cpp). Whether a specimen shows it is a
question about its stress signal: how often and how far the deviator q = -(sigma_zz -
(sigma_xx + sigma_yy)/2) (compression positive) falls, how long a fall lasts, and whether the
signal repeats at the contacts' slip period. A saw-tooth hidden by the sampling would show
at a fine sampling interval and vanish when the same signal is subsampled or averaged over
the cases' 0.4 ms interval; this script prints both.

Usage: scripts/s3-stick-slip-signal.py RESULTS_DIR... [--from STRAIN]
  RESULTS_DIR holds a dem.h5 of a run (`geocomp dem`), best with a fine sampling interval,
  e.g. the shipped stick-slip cases with `set sampling interval = 0.00001`.
  --from: the axial compressive strain from which the signal is the sliding one (0.025).
Reads with h5dump (Debian hdf5-tools), no other dependency.
"""
import math
import re
import subprocess
import sys


def dataset(path, name):
    """The numbers of one dataset, flattened (h5dump text)."""
    out = subprocess.run(['h5dump', '-y', '-w', '0', '-d', name, path], capture_output=True, text=True,
                         check=True).stdout
    start = out.index('DATA {') + len('DATA {')
    body = out[start:out.index('}', start)]
    return [float(x) for x in re.findall(r'[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?', body)]


def drops(q):
    """(size, samples) of every fall from a local maximum to the next local minimum."""
    out, i, n = [], 0, len(q)
    while i < n - 1:
        if q[i + 1] < q[i]:
            j = i
            while j < n - 1 and q[j + 1] <= q[j]:
                j += 1
            out.append((q[i] - q[j], j - i))
            i = j
        else:
            i += 1
    return out


def describe(label, q, strain_span, dt):
    n = len(q)
    mean = sum(q) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in q) / n)
    d = drops(q)
    over1 = [x for x in d if x[0] > 0.01 * mean]
    over5 = [x for x in d if x[0] > 0.05 * mean]
    largest = max((x[0] for x in d), default=0.0)
    duration = sum(x[1] for x in over1) / len(over1) * dt if over1 else 0.0
    print(f"  {label:30s} n {n:5d}  mean q {mean / 1e3:6.2f} kPa  sd {100 * sd / mean:5.2f} %  "
          f"drops > 1 % of q: {len(over1) / strain_span:6.1f} per % strain, > 5 %: {len(over5) / strain_span:5.1f}  "
          f"largest {100 * largest / mean:5.1f} %  mean fall time (> 1 %) {duration * 1e6:6.0f} us")


def autocorrelation(q, lags, window):
    """Autocorrelation of q less its moving mean over `window` samples."""
    n = len(q)
    r = []
    for i in range(n):
        a, b = max(0, i - window // 2), min(n, i + window // 2)
        r.append(q[i] - sum(q[a:b]) / (b - a))
    v = sum(x * x for x in r) / n
    return [sum(r[i] * r[i + k] for i in range(n - k)) / (n - k) / v for k in lags]


def main(argv):
    start = 0.025
    dirs = []
    it = iter(argv)
    for a in it:
        if a == '--from':
            start = float(next(it))
        else:
            dirs.append(a)
    if not dirs:
        sys.exit(__doc__)
    for d in dirs:
        f = d + '/dem.h5'
        t, s, sm, e = (dataset(f, '/response/' + x) for x in ('time', 'stress', 'stress_mean', 'strain'))
        dt = t[1] - t[0]
        rows = [k for k in range(len(t)) if -e[9 * k + 8] >= start]
        span = 100.0 * abs(e[9 * rows[-1] + 8] - e[9 * rows[0] + 8])
        q = [-(s[9 * k + 8] - 0.5 * (s[9 * k] + s[9 * k + 4])) for k in rows]
        qm = [-(sm[9 * k + 8] - 0.5 * (sm[9 * k] + sm[9 * k + 4])) for k in rows]
        print(f"{d}: sampled every {dt * 1e6:.1f} us; from {100 * start:.1f} % axial strain, {span:.2f} % of it")
        describe('every sample', q, span, dt)
        for m in (4, 40):
            describe(f'every {m}th sample', q[::m], span, m * dt)
            means = [sum(qm[i:i + m]) / m for i in range(0, len(qm) - m + 1, m)]
            describe(f'means over {m} samples', means, span, m * dt)
        lags = [1, 2, 5, 10, 20, 40, 80]
        acf = autocorrelation(q, lags, 100)
        print('  autocorrelation (less the moving mean over 100 samples): ' +
              '  '.join(f'{k * dt * 1e6:.0f} us {c:+.2f}' for k, c in zip(lags, acf)))


if __name__ == '__main__':
    main(sys.argv[1:])
