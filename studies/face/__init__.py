"""Where on the face to hit: maps of the whole string face (:mod:`~studies.face.maps`),
the sweet spots in one table (:mod:`~studies.face.sweetspots`), and the landmarks players
ask about, the hand and the centre of percussion (:mod:`~studies.face.landmarks`).
"""
