#version 3.7;
#declare F = function(n) { prod(i, 1, n, i) + sum(k, 1, 3e84, k * k) }
#debug str(F(3), 0, 3)
