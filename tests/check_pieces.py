# Loads the last output of a run (the last record of solution.pvd) in
# ParaView (pvpython) and prints its number of cells, the range of the
# subdomain field and whether every piece its .pvtu record lists exists.
# Usage: pvpython check_pieces.py results-directory
import os
import re
import sys

from paraview import servermanager
from paraview.simple import PVDReader

directory = sys.argv[1]
pvd = open(os.path.join(directory, "solution.pvd")).read()
last = re.findall(r'file="([^"]+\.pvtu)"', pvd)[-1]
pieces = re.findall(r'<Piece Source="([^"]+)"',
                    open(os.path.join(directory, last)).read())
print("pieces listed: %d, all present: %s" %
      (len(pieces), "OK" if all(os.path.exists(os.path.join(directory, p))
                                for p in pieces) else "FAILED"))
reader = PVDReader(FileName=os.path.join(directory, "solution.pvd"))
reader.UpdatePipeline(reader.TimestepValues[-1])
data = servermanager.Fetch(reader)
subdomain = data.GetPointData().GetArray("subdomain").GetRange()
print("cells %d, subdomains %d to %d" %
      (data.GetNumberOfCells(), subdomain[0], subdomain[1]))
