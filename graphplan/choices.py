"""The names a scene and the command line choose among: the languages, the sheet formats, the pieces of a run.

Apart from :mod:`graphplan.scene`, which reads them, so that the command line lists them (``graphplan --help``,
its options' choices) without loading the scene's readers and the groups' solvers under them.
"""

LOCALES = ("en", "ru", "zh")
SHEETS = ("A1", "A2", "A3", "A4", "none")
# Every piece a run can deliver, in the order a course project presents them (graphplan.deliverables):
# the seven of the scene contract, then the kinematic diagrams, the load diagrams the force analysis reads, the
# accuracy report, the machine's dynamics, the rotor's balancing, the vibration, the sheets and the report figures.
OUTPUT_PIECES = ("positions", "velocity", "acceleration", "diagrams", "load_diagrams", "forces", "lever", "errors",
                 "accuracy", "note",
                 "dynamics", "balancing", "vibration", "sheets", "figures")

__all__ = ["LOCALES", "OUTPUT_PIECES", "SHEETS"]
