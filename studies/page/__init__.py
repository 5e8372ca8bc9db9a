"""The interactive page (``racket-impact app``, Shiny for Python), in one room.

* :mod:`~studies.page.app`: the page itself, its layout and reactive graph;
* :mod:`~studies.page.dashboard`: what it shows, computed apart from the page (tested
  without a browser);
* :mod:`~studies.page.inputs`, :mod:`~studies.page.guard`: its controls read and checked;
* :mod:`~studies.page.strings`, :mod:`~studies.page.strokes`, :mod:`~studies.page.cards`,
  :mod:`~studies.page.conditions`: the strings, strokes, cards and conditions it shows;
* :mod:`~studies.page.plots`: its figures.

Every number comes from the same functions as the command line and the API.
"""
