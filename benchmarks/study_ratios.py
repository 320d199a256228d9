"""The table of an adaptive study shared by the benchmark scripts: each
adaptive run's estimated errors (tools/study.py's estimated_* columns: the
difference from the reference plus the reference's own estimated error)
over those of the uniform run of its finest level."""
import csv


def print_ratios(study_csv, finest_of_level):
    """finest_of_level(k): the finest mesh level of the adaptive runs of
    study level k (their Maximum level); they are compared with the uniform
    run of that mesh level, if the study ran it."""
    rows = list(csv.DictReader(open(study_csv)))
    uniform = {int(r["mesh_level"]): r for r in rows
               if r["configuration"].startswith("uniform")}
    reference = uniform[max(uniform)]
    levels = sorted(set(int(r["level"]) for r in rows
                        if r["configuration"].startswith("adaptive")))
    for level in levels:
        finest = finest_of_level(level)
        if finest not in uniform or finest == max(uniform):
            continue
        u = uniform[finest]
        tau = float(u["tau"])
        print("The uniform level-%d run's estimated errors: energy %.3g, force "
              "%.3g, position %.3g m; the level-%d reference's own: %.3g, "
              "%.3g, %.3g m (a ratio whose error is near the reference's is "
              "not resolved)" % ((finest,) + tuple(
                  float(u["estimated_" + k]) for k in
                  ("energy_max", "force_max", "position_max")) +
                  (max(uniform),) + tuple(
                  float(reference["estimated_" + k]) for k in
                  ("energy_max", "force_max", "position_max"))))
        print("Adaptive runs of finest level %d against the uniform level-%d "
              "run (%s DoFs, %.3g s):" % (finest, finest, u["dofs"],
                                          float(u["time"])))
        width = max(len(r["configuration"]) for r in rows)
        print("%-*s %8s %10s %10s %10s %16s %10s" % (
            width, "configuration", "DoFs", "energy", "force", "position",
            "release/steps", "time"))
        for r in rows:
            if not r["configuration"].startswith("adaptive") or \
                    int(r["level"]) != level:
                continue

            def ratio(key):
                return (float(r["estimated_" + key]) /
                        float(u["estimated_" + key]))
            release = "%.0f / %.0f" % (float(r["release"]) / tau,
                                       float(u["release"]) / tau)
            print("%-*s %8s %10.2f %10.2f %10.2f %16s %10.2f" % (
                width, r["configuration"], r["dofs"], ratio("energy_max"),
                ratio("force_max"), ratio("position_max"), release,
                float(r["time"]) / float(u["time"])))
    print("(ratios of the estimated errors, adaptive over uniform; DoFs: the "
          "largest; release/steps: the last release's difference from the "
          "reference's in steps, adaptive / uniform; time: ratio of the "
          "wall times less the comparisons)")
