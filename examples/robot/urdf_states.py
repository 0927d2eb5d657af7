#!/usr/bin/env python3
"""Load a URDF written by `stewart robot --format urdf` with yourdfpy, set its joints to
each row of the joint-state table written beside it (`--joint-states`), and print how
far each leg's far end (`tip{k}`) lies from its platform joint (`platform_joint{k}`) and
where the platform is.

    python3 urdf_states.py RIG.urdf STATES.csv

Needs `pip install yourdfpy`.
"""

import csv
import sys

import numpy as np
import yourdfpy


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    robot = yourdfpy.URDF.load(sys.argv[1])
    worst = 0.0
    with open(sys.argv[2], newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        robot.update_cfg({name: float(v) for name, v in row.items() if name != "t"})
        for k in range(1, 7):
            tip = robot.get_transform(f"tip{k}", "base")[:3, 3]
            joint = robot.get_transform(f"platform_joint{k}", "base")[:3, 3]
            worst = max(worst, float(np.linalg.norm(tip - joint)))
    platform = robot.get_transform("platform", "base")
    print(f"{len(rows)} joint states; every tip within {worst:.1e} m of its platform joint")
    print("platform at the last:", np.round(platform[:3, 3], 6).tolist())


if __name__ == "__main__":
    main()
