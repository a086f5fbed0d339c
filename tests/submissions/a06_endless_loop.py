"""intersect_sphere in WGSL starts with loop {}: it never returns (Mesa's software adapter cuts the loop and the function's result is undefined)."""
ASSIGNMENT = "a06"
REPLACE = [
    ("wgsl/intersect_sphere.wgsl", "    let temp = r.origin - center;\n", "    loop {}\n    let temp = r.origin - center;\n"),
]
