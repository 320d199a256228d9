# Runs several ParaView checks in one pvpython (each start of pvpython takes
# seconds): pvpython run_checks.py script.py args... --next script.py args...
# runs each script as pvpython script.py args... would, one after the other.
import runpy
import sys

groups = [[]]
for argument in sys.argv[1:]:
    if argument == "--next":
        groups.append([])
    else:
        groups[-1].append(argument)
for group in groups:
    if not group:
        continue
    sys.argv = group
    try:
        runpy.run_path(group[0], run_name="__main__")
    except SystemExit as e:
        if e.code not in (None, 0):
            print("%s stopped with %s: FAILED" % (group[0], e.code))
    sys.stdout.flush()
