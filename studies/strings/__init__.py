"""Strings for a stringer (issue 35): one racket strung with each string in turn
(:mod:`~studies.strings.table`, ``racket-impact strings``) and the string bed as the user
types it on the command line and in TOML (:mod:`~studies.strings.inputs`).  The strings
themselves are in :mod:`racket.strings`.
"""
