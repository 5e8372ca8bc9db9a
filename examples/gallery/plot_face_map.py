"""
The string face
===============

e_A over the face of a spec-sheet racket (the Pure Drive), ball at 16.5 m/s on the racket
at rest: the sweet area, the node line and the centre of percussion.
"""

from racket import CATALOG, tennis_ball
from studies.maps import face_map
from studies.plots import plot_face_map

face = face_map(CATALOG["pure-drive-2021"].racket(), tennis_ball(), 16.5)
ax = plot_face_map(face)
print(f"sweet area {face.sweet_area_cm2:.1f} cm^2")
