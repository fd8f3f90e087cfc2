"""What the history checkers share: the columns of a history CSV and a named check against a
limit that prints the value and remembers a failure (check_contact.py, check_surface_contact.py).
"""
import csv

import numpy as np


class HistoryChecks:
    def __init__(self, path):
        self.rows = list(csv.DictReader(open(path)))
        self.ok = True

    def col(self, name):
        return np.array([float(r[name]) for r in self.rows])

    def check(self, name, value, limit):
        good = abs(value) <= limit
        self.ok = self.ok and good
        print("%s %.3g (limit %.3g)%s" % (name, value, limit, "" if good else "  FAILED"))

    def check_incline_slide(self, velocity, tan, mu, g=1.0):
        """A body sliding down an incline (gravity turned by theta, tan(theta) = tan): the
        least-squares slope of `velocity` over t in [1, 2] = g (sin - mu cos) within 1 %."""
        t, th = self.col("time"), np.arctan(tan)
        w = (t >= 1.0) & (t <= 2.0)
        a = np.polyfit(t[w], velocity[w], 1)[0]
        exact = g * (np.sin(th) - mu * np.cos(th))
        print("acceleration %.6f, exact %.6f" % (a, exact))
        self.check("acceleration error (relative)", a / exact - 1, 1e-2)

    def check_at_rest(self, displacement, size=1.0):
        """A body held by friction: the mean displacement drifts by less than 1e-6 of its size
        between t in [3, 3.5] and [3.5, 4]."""
        t = self.col("time")
        w1, w2 = (t >= 3.0) & (t < 3.5), (t >= 3.5)
        self.check("drift / block size",
                   (displacement[w2].mean() - displacement[w1].mean()) / size, 1e-6)
