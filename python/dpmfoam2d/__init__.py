# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmfoam2d: what a dpmFoam2D case writes, read into numpy, and the
project's commands (console scripts of the package; the project's bin/
holds launchers of the same functions).

    import dpmfoam2d as dpm
    M = dpm.lacey("myCase")              # M(t): columns Time, M, ...
    p = dpm.particles_at("myCase", 2.0)  # the particle file nearest t = 2 s

Modules:
    particles       particle files (<case>/particles/<t>.h5, the XDMF index)
    tables          function-object tables (Lacey, segregation), joined
                    over restarts
    fields          gas fields (internal fields of volScalar/VectorFields,
                    cell centres and volumes, time directories)
    bed_statistics  bubbles, bed height and particle motion (dpmBedStatistics)
    rise_time       when the particles of a class reach the bed's surface
                    (dpmRiseTime)
    pictures        snapshots, movies, M(t) plots, ParaView (dpmSnapshot,
                    dpmMovie, dpmPlotMixing, dpmPictures, dpmParaView)
    statistics      Welch intervals, equivalence tests (TOST) and V&V 20's
                    validation uncertainty, for comparisons with experiments
    study           the study runner and its results (dpmStudy)
    project         the project's tree and programs, from its environment
                    (DPMFOAM2D_PROJECT, PATH), where a function needs them
"""

__version__ = "0.1.0"

from .particles import FIELDS, list_times, nearest_time, read as particles_at, read_particles
from .tables import lacey, read_dat, read_postprocessing, segregation, study_table
from .fields import cell_geometry, internal_field, time_dirs

__all__ = ["FIELDS", "list_times", "nearest_time", "particles_at", "read_particles", "lacey",
           "read_dat", "read_postprocessing", "segregation", "study_table", "cell_geometry",
           "internal_field", "time_dirs", "__version__"]
