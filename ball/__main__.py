"""``python -m ball``: the paper's unhappy-ball collisions (Figs. 2-4) and the tennis-ball
estimate (Eq. 6), simulated and set beside the published numbers."""

from __future__ import annotations

import numpy as np

from ball import WALL, Ball, LinearHysteresis, LinearSpring, SineLaw, collide, unhappy_cor


def main() -> None:
    unhappy = Ball(0.0103, SineLaw(k0=2e4))
    rows = []
    fig2 = collide(unhappy, WALL, 4.0)
    t_peak = fig2.history.t[np.argmax(fig2.history.force)]
    rows.append(("Fig. 2 force peak time [ms]", 0.36, t_peak * 1e3))
    rows.append(("Fig. 2 rebound speed [m/s]", 0.0, fig2.v_a_after))
    for fig, k2, happy_after, unhappy_after, e in [
        ("Fig. 3", 2e4, 3.034, 0.966, 0.517),
        ("Fig. 4", 1e5, 2.00, 2.00, 0.001),
    ]:
        r = collide(unhappy, Ball(0.0103, LinearSpring(k2)), 4.0)
        rows.append((f"{fig} happy ball after [m/s]", happy_after, r.v_b_after))
        rows.append((f"{fig} unhappy ball after [m/s]", unhappy_after, r.v_a_after))
        rows.append((f"{fig} e (Eq. 16: {max(unhappy_cor(2e4, k2), 0):.3f})", e, r.e))
    tennis = collide(Ball(0.057, LinearHysteresis(4e4, 0.75)), Ball(1e12, LinearSpring(4e4)), 10.0)
    rows.append(("Tennis ball on head-clamped strings, e (Eq. 6)", 0.88, tennis.e))
    width = max(len(r[0]) for r in rows)
    print(f"{'claim':<{width}}  {'paper':>8}  {'simulated':>10}")
    for claim, paper, sim in rows:
        print(f"{claim:<{width}}  {paper:>8.3f}  {sim:>10.4f}")


if __name__ == "__main__":
    main()
