"""Strokes and courts (issue 36): the ball's speed, launch and spin after each stroke
(:mod:`~studies.strokes.stroke`, ``racket-impact stroke``) and its bounce on each court with
the court's pace (:mod:`~studies.strokes.court`, ``racket-impact court``).
"""
