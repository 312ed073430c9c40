import json,sys,statistics as st,glob
rows={}
for f in sorted(glob.glob(sys.argv[1]+'/*/results.json')):
  lab=f.split('/')[-2].rsplit('-',1)[0]
  d=json.load(open(f))
  c={c['technique'][7:]:{p['name']:p['stats_ms']['median'] for p in c['timing']['passes']} for c in d['cases']}
  r={c['technique'][7:]:c['ratio']['median'] for c in d['cases']}
  rows.setdefault(lab,[]).append((r['hard'],r['vsm'],c['hard']['lit']/c['hard']['shadow_map'],c['pcf']['lit']/c['pcf']['shadow_map'],c['vsm']['lit']/c['vsm']['moment_map']))
print('label n hard/pcf vsm/pcf hard-lit/sm pcf-lit/sm vsm-lit/mm (medians)')
for k,v in rows.items():
  print(k, len(v), ' '.join('%.3f'%st.median(x) for x in zip(*v)))
