"""``racket-impact app``: the interactive page, served on this machine."""

from __future__ import annotations

from studies.cli.options import _count


def add_app(sub) -> None:
    """The ``app`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("app", help="the interactive page, served on this machine")
    p.add_argument("--host", default="127.0.0.1", help="address to serve on (default 127.0.0.1)")
    p.add_argument(
        "--port", type=int, default=8050, help="port (default 8050; the docs' server takes 8000)"
    )  # studies.page.app.DEFAULT_PORT, not imported here: Shiny is optional
    p.set_defaults(func=cmd_app)


def cmd_app(args) -> int:
    """``racket-impact app``."""
    port = int(_count("--port", args.port, 1024, 65535))
    try:
        from studies.page.app import run
    except ImportError:
        raise ValueError("the page needs Shiny: pip install 'racket-impact[app]'") from None

    def announce(url: str) -> None:  # once the port is bound (a port in use: one line)
        print(f"racket-impact: the page is at {url} (Ctrl-C stops it)", flush=True)

    run(args.host, port, announce)
    return 0
