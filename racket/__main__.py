"""``python -m racket``: the paper's Sec. VII numbers from the flexible-racket model."""

from __future__ import annotations

import numpy as np

from racket import impact, paper_racket, tennis_ball


def main() -> None:
    racket, ball = paper_racket(), tennis_ball()
    x = np.linspace(0.0, 0.32, 321)
    r = impact(racket, ball, x, 10.0)
    node = racket.beam.modes.nodes(1)[0]
    i_max = int(np.argmax(r.e))
    centre = racket.strings.center
    rows = [
        ("largest e (at the mode-1 node)", 0.86, r.e[i_max]),
        (f"  where [m from the tip] (node at {node:.3f} m)", node, x[i_max]),
        ("e at the tip (0.01 m)", 0.54, np.interp(0.01, x, r.e)),
        ("e at the throat (0.30 m)", 0.71, np.interp(0.30, x, r.e)),
        ("largest e_A is at [m from the tip]", float("nan"), x[np.argmax(r.e_A)]),
        (
            "effective mass / ball mass at the string centre",
            3.0,
            np.interp(centre, x, r.effective_mass) / ball.mass,
        ),
    ]
    width = max(len(row[0]) for row in rows)
    print("Paper racket (0.68 m, 0.34 kg, f1 = 120 Hz, strings 4e4 N/m), ball at 10 m/s")
    print(f"{'claim':<{width}}  {'paper':>7}  {'simulated':>9}")
    for claim, paper, sim in rows:
        print(f"{claim:<{width}}  {paper:>7.3f}  {sim:>9.3f}")


if __name__ == "__main__":
    main()
