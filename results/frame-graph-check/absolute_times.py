#!/usr/bin/env python3
"""Absolute GPU frame times of two builds from runs made alternately (before-k, after-k, ...).

usage: absolute_times.py BEFORE_GLOB AFTER_GLOB [metric] [--passes]
Per case: the median over runs of each run's median GPU frame time (or wall), the ratio
after/before of those medians, and a 95 % interval for it from resampling the runs (pairs k
kept together, so drift that hits both builds of a pair cancels). The last row pools every
case: the geometric mean of the per-case ratios, resampled the same way. --passes adds each
pass's median over runs of its per-run medians.
"""
import glob, json, math, random, statistics as st, sys

def load(pattern, metric):
    runs = []
    for f in sorted(glob.glob(pattern + '/results.json')):
        d = json.load(open(f))
        runs.append({c['id']: c['timing'][metric]['stats_ms']['median'] for c in d['cases'] if c.get('timing')})
    return runs

args = [a for a in sys.argv[1:] if a != '--passes']
metric = args[2] if len(args) > 2 else 'gpu_frame'
before, after = load(args[0], metric), load(args[1], metric)
if not before or not after:
    sys.exit(f'absolute_times.py: no results.json under {args[0] if not before else args[1]} '
             '(the globs are relative to the current folder; quote them so the shell leaves them alone)')
n = min(len(before), len(after))
before, after = before[:n], after[:n]
cases = [c for c in before[0] if all(c in r for r in before + after)]
random.seed(1)
B = 4000
draws = [[random.randrange(n) for _ in range(n)] for _ in range(B)]

def ratio(idx, case):
    return st.median(after[i][case] for i in idx) / st.median(before[i][case] for i in idx)

def interval(f):
    vals = sorted(f(d) for d in draws)
    return vals[int(0.025 * B)], vals[int(0.975 * B) - 1]

print(f'{n} runs of each build, {metric} (ms): median over runs of each run\'s median')
print(f'| case | before | after | after / before | 95 % interval |')
print('|---|---:|---:|---:|---|')
for c in cases:
    lo, hi = interval(lambda d: ratio(d, c))
    print(f'| {c} | {st.median(r[c] for r in before):.3f} | {st.median(r[c] for r in after):.3f} | '
          f'{ratio(range(n), c):.3f} | {lo:.3f} - {hi:.3f} |')
geo = lambda idx: math.exp(st.mean(math.log(ratio(idx, c)) for c in cases))
lo, hi = interval(geo)
print(f'| all {len(cases)} cases (geometric mean) | | | {geo(range(n)):.3f} | {lo:.3f} - {hi:.3f} |')

if '--passes' in sys.argv:
    def pass_medians(pattern):
        runs = []
        for f in sorted(glob.glob(pattern + '/results.json'))[:n]:
            d = json.load(open(f))
            runs.append({(c['id'], p['name']): p['stats_ms']['median'] for c in d['cases'] if c.get('timing')
                         for p in c['timing']['passes']})
        return runs
    pb, pa = pass_medians(args[0]), pass_medians(args[1])
    print()
    print('| case | pass | before | after | after / before |')
    print('|---|---|---:|---:|---:|')
    for key in pb[0]:
        b, a = st.median(r[key] for r in pb), st.median(r[key] for r in pa)
        print(f'| {key[0]} | {key[1]} | {b:.3f} | {a:.3f} | {a / b:.3f} |')
