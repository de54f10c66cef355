"""What each polygon shows, in order (`constructions`: every step's construction, collected
per polygon) and at which scale (`scales`: 1, 2, 2.5 or 5 x 10^k per cm, chosen in one
place for every view)."""
