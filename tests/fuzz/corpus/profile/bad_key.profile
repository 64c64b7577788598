name = x
bogus = 3
