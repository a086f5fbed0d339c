"""MultiJittered.generate_samples leaves every set in the canonical arrangement: no shuffle."""
ASSIGNMENT = "a10"
REPLACE = [
    ("sampling/multi_jittered.py", "                        self._swap(base + cell(i, j), base + cell(i, k), axis)\n",
     "                        pass\n"),
]
