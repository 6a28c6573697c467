"""Running the diskimpact of build/ from a bench script, and the parameter
file of the plastic benches' sphere."""
import os
import subprocess
import time

BINARY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                      "build", "diskimpact")


def run_diskimpact(prm, ranks):
    """Run build/diskimpact on @p prm on @p ranks MPI ranks (its output
    discarded, an error raised if it fails); return the wall time [s]."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    subprocess.run(["mpirun", "-np", str(ranks), BINARY, prm],
                   check=True, stdout=subprocess.DEVNULL, env=env)
    return time.time() - start


# The plastic benches' sphere (params/sweep_plastic_sphere.prm): its yield
# stress (Y = 0.002 E* at nu = 0.3, E = 1) and speed of first yield v_y / c
# on the rigid wall (docs/validation/plastic-sphere.md).
PLASTIC_SPHERE_YIELD_STRESS = 0.0021978022
PLASTIC_SPHERE_YIELD_SPEED = 9.22133e-7


def plastic_sphere_prm(directory, refinements, impact, stepping,
                       task="impact"):
    """Task @p task of the elastic-perfectly-plastic sphere of
    params/sweep_plastic_sphere.prm (nu = 0.3, Y = 0.002 E*, penalty factor
    100), output in @p directory, with @p refinements global refinements
    and the lines @p impact and @p stepping of subsections Impact and Time
    stepping."""
    return f"""set Task = {task}
set Output directory = {directory}
subsection Geometry
  set Body = sphere
  set Global refinements = {refinements}
end
subsection Material
  set Poisson ratio = 0.3
  set Yield stress = {PLASTIC_SPHERE_YIELD_STRESS}
end
subsection Contact
  set Penalty factor = 100
end
subsection Impact
{impact}end
subsection Time stepping
{stepping}end
"""
