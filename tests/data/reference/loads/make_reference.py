"""The reference numbers of tests/loads/loads_test.cpp, from openfast_toolbox's own
reader and fatigue functions. Run once, by hand, with Debian's python3 (numpy,
scipy, pandas) from this folder:

    /usr/bin/python3 make_reference.py PATH/TO/openfast_toolbox

(PATH/TO/openfast_toolbox: a checkout of github.com/OpenFAST/openfast_toolbox,
commit d34b283c1aa1ab2360634a51a6ea95f3fbbdefeb). Not part of the build or the tests.
"""
import sys

sys.path.insert(0, sys.argv[1])
import numpy as np
from scipy import stats
from openfast_toolbox.io.fast_output_file import FASTOutputFile
from openfast_toolbox.tools.fatigue import equivalent_load

df = FASTOutputFile('fastout_allnodes.outb').toDataFrame()
t = df['Time_[s]']
print('rows', len(t), 'columns', df.shape[1], 't0', repr(t.iloc[0]), 't1', repr(t.iloc[-1]))
for ch in ['RootMyc1_[kN-m]', 'TwrBsMyt_[kN-m]', 'RotSpeed_[rpm]']:
    y = df[ch].values
    print(ch, 'y[0]', repr(y[0]), 'y[50]', repr(y[50]), 'y[-1]', repr(y[-1]))
    # pCrunch's AeroelasticOutput statistics (np.std, scipy.stats.moment).
    m2, m3, m4 = (stats.moment(y, moment=k) for k in (2, 3, 4))
    print(' stats mean %r std %r min %r max %r skew %r kurt %r'
          % (np.mean(y), np.sqrt(m2), y.min(), y.max(), m3 / np.sqrt(m2)**3, m4 / m2**2))
    for m in [1, 4, 10]:
        # equivalent_load's defaults (Teq=1, bins=100, meanBin=True, binStartAt0=False)
        # with ASTM E1049 counting; its default counting, 'rainflow_windap', for comparison.
        print(' m', m, 'astm', repr(equivalent_load(t, df[ch], m=m, method='rainflow_astm')),
              'windap', repr(equivalent_load(t, df[ch], m=m)))
g = 'FASTOutBin.outb'
d2 = FASTOutputFile(g).toDataFrame()
print(g, d2.shape, list(d2.columns)[:5], repr(d2.iloc[3, 0]), repr(d2.iloc[3, 2]), repr(d2.iloc[-1, -1]),
      list(d2.columns)[-1])
