"""A measured profile trace (X3P, FeatureType PRF, 40 mm of Gaussian heights, Rq 0.3 um) at a given
spacing, and the shipped deterministic case with it as both flanks' topography and elements of that
spacing. Usage: make_inputs.py FOLDER SPACING_UM ELEMENT_UM (writes FOLDER/trace.x3p, FOLDER/trace.toml)."""
import hashlib
import random
import re
import struct
import sys
import zipfile
from pathlib import Path

folder, spacing_um, element_um = Path(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
root = Path(__file__).resolve().parents[3]
n, r = int(round(40e3 / spacing_um)), random.Random(3)
data = b''.join(struct.pack('<d', r.gauss(0, 3e-7)) for _ in range(n))
xml = f'''<?xml version="1.0" encoding="UTF-8"?><p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>PRF</FeatureType><Axes>
<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{spacing_um * 1e-6:.17g}</Increment><Offset>0</Offset></CX>
<CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1>
<Record3><MatrixDimension><SizeX>{n}</SizeX><SizeY>1</SizeY><SizeZ>1</SizeZ></MatrixDimension>
<DataLink><PointDataLink>bindata/data.bin</PointDataLink><MD5ChecksumPointData>{hashlib.md5(data).hexdigest()}</MD5ChecksumPointData></DataLink></Record3></p:ISO5436_2>'''
with zipfile.ZipFile(folder / 'trace.x3p', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('main.xml', xml)
    z.writestr('bindata/data.bin', data)
s = (root / 'gears/m6z30-deterministic.toml').read_text().replace('../materials/', f'{root}/materials/')
s = re.sub(r'\[pinion\.flank\.profile\].*?(?=\n\[wheel\])', '[pinion.flank.topography]\nfile = "trace.x3p"\nform = 0\n', s, flags=re.S)
s = re.sub(r'\[wheel\.flank\.profile\].*?(?=\n\[roughness\])', '[wheel.flank.topography]\nfile = "trace.x3p"\nform = 0\n', s, flags=re.S)
s = s.replace('element_size = "0.5 um"', f'element_size = "{element_um} um"')
(folder / 'trace.toml').write_text(s)
