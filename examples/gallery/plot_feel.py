"""
The feel at the hand
====================

The handle's velocity and acceleration at the grip of a hand-held racket after an impact at
the string centre, and the acceleration's spectrum.
"""

from dataclasses import replace

from racket import CATALOG, tennis_ball
from racket.feel import hand_feel
from studies.plots import plot_hand_feel

racket = replace(CATALOG["pure-drive-2021"].racket(), support="hand-held")
feel = hand_feel(racket, tennis_ball(), racket.strings.center, 20.0)
axes = plot_hand_feel(feel)
