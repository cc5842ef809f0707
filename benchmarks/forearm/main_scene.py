"""The main scene as the forearm benchmarks run it: its prm, the overrides
that keep a run from writing fields, section and profile (timings then
measure the solve alone), and the MPI ranks `./ssc.sh run` uses on this
2-core machine."""
import os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "common"))
import ssc_runner  # noqa: E402

SCENE = os.path.join(ssc_runner.ROOT, "prm", "forearm_indentation.prm")
NO_PICTURES = ["Run/Write fields=false", "Punch/Section=false",
               "Punch/Profile length=0"]
SHIPPED_RANKS = 2
