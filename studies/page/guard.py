"""The interactive page's door: every message the browser sends over the page's websocket
is read here before Shiny sees it, and one Shiny cannot take is turned away with an error
card in the page (:data:`ERROR_OUTPUT`) and one line on the server's stderr, the session
left alive.

Why here: Shiny ends a session on a message it cannot take and prints a traceback (an
update before the first message: "Invalid method for the current session state"), or
stops reading without closing the socket (a message that is not JSON, or has no method:
the page then hears nothing until the browser gives up).  Both happen inside
``shiny.session.Session._run`` before any of the app's code runs, so the app cannot catch
them; it can only keep such messages from reaching Shiny.  What the messages' values mean
is checked by the page itself (:func:`studies.page.inputs.page_inputs`).
"""

from __future__ import annotations

import html
import json
import math
import re
import sys
from collections.abc import Callable
from dataclasses import dataclass

ERROR_OUTPUT = "message_error"
"""The page's output that shows why a message was turned away."""

MESSAGE_MAX_CHARS = 1_000_000
"""The longest message the page takes [characters]: far above the page's own (its first,
the longest, is about 3 kB; ASSUMPTION: a margin of 300 times); a longer one is turned away
unread."""

PLOT_PX_MAX = 8000.0
"""The widest or tallest plot the page draws [CSS px]: an 8K screen is 7680 px wide
(ASSUMPTION: a plot is never wider than the screen)."""

PIXEL_RATIO_MAX = 8.0
"""The largest device pixel ratio the page draws for [-] (ASSUMPTION: phones reach 3.5,
a browser's zoom multiplies it, 200 % on such a phone about 7): with :data:`PLOT_PX_MAX`, a
plot stays under matplotlib's 65536 px (8000 x 8 = 64000)."""

TYPES = ("shiny.number",)
"""The input types the page's controls send (its numeric inputs; the others send none)."""

_SIZE = re.compile(r"^\.clientdata_output_.+_(width|height)$")


def _number_in(value, low: float, high: float) -> bool:
    """Whether ``value`` is a number in (``low``, ``high``]."""
    ok = isinstance(value, int | float) and not isinstance(value, bool)
    return ok and math.isfinite(value) and low < value <= high


def _bad_input(key: str, value) -> str | None:
    """Why Shiny cannot take the input ``key`` (as sent, "id" or "id:type") with ``value``,
    or None: a type no control sends, or client data that Shiny uses unchecked (the plots'
    sizes, the pixel ratio, whether an output is hidden, the page's query) of the wrong type
    or beyond what the page draws.
    """
    name, _, kind = key.partition(":")
    if kind and kind not in TYPES:
        return f"input {key[:60]!r} has a type the page's controls do not send"
    if _SIZE.match(name) and not _number_in(value, -1.0, PLOT_PX_MAX):
        return f"{name[:60]} must be a number of px in [0, {PLOT_PX_MAX:g}]"
    if name == ".clientdata_pixelratio" and not _number_in(value, 0.0, PIXEL_RATIO_MAX):
        return f"{name} must be a number in (0, {PIXEL_RATIO_MAX:g}]"
    if name.startswith(".clientdata_output_") and name.endswith("_hidden"):
        return None if isinstance(value, bool) else f"{name[:60]} must be true or false"
    if name == ".clientdata_url_search" and not isinstance(value, str):
        return f"{name} must be a string"
    return None


def refusal(text, started: bool) -> str | None:
    """Why the page's websocket message ``text`` cannot go to Shiny, or None if it can.

    Parameters
    ----------
    text : str or None
        The message (None: a binary one).
    started : bool
        Whether the session's first message ("init") has gone to Shiny.
    """
    if not isinstance(text, str):
        return "a binary message (the page sends text)"
    if len(text) > MESSAGE_MAX_CHARS:
        return f"a message of {len(text)} characters (the page takes {MESSAGE_MAX_CHARS})"
    try:
        message = json.loads(text)
    except (ValueError, RecursionError):
        return "a message that is not JSON"
    method = message.get("method") if isinstance(message, dict) else None
    if not isinstance(method, str):
        return "a message without a method"
    if method not in ("init", "update"):
        if "tag" in message and "args" in message:  # a request Shiny answers itself
            return None if started else f"a {method!r} request before the first message"
        return f"a message of the unknown method {method[:60]!r}"
    if started == (method == "init"):
        return "a second first message" if started else "an update before the first message"
    data = message.get("data")
    if not isinstance(data, dict):
        return f"an {method} message whose data is not an object"
    for key, value in data.items():
        why = key.count(":") > 1 and f"input {key[:60]!r} has more than one ':'"
        why = why or _bad_input(key, value)
        if why:
            return f"an {method} message where {why}"
    return None


def _card(said: str) -> str:
    """The Shiny message that shows ``said`` as an error card in :data:`ERROR_OUTPUT`."""
    line = f"The page sent the server {said}: it was ignored. Reload the page."
    card = f'<div class="alert alert-danger py-2 mb-2" id="message-error">{html.escape(line)}</div>'
    return json.dumps({"values": {ERROR_OUTPUT: {"html": card, "deps": []}}})


@dataclass(eq=False)  # hashed and compared as itself, as any app
class PageGuard:
    """The ASGI app ``app`` (the page's Shiny app) behind :func:`refusal`: a message it
    turns away never reaches Shiny; the page gets an error card, stderr one line.

    Parameters
    ----------
    app : callable
        The ASGI app.
    """

    app: Callable

    async def __call__(self, scope, receive, send):
        """Serve one ASGI connection (an HTTP request or a websocket)."""
        if scope["type"] != "websocket":
            await self.app(scope, receive, send)
            return
        started = False

        async def checked():
            nonlocal started
            while True:
                event = await receive()
                if event["type"] != "websocket.receive":
                    return event
                said = refusal(event.get("text"), started)
                if said is None:  # before the start, only "init" gets through
                    started = True
                    return event
                print(f"racket-impact app: turned away {said}", file=sys.stderr, flush=True)
                await send({"type": "websocket.send", "text": _card(said)})

        await self.app(scope, checked, send)
