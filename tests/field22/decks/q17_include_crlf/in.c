pair_coeff * * hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
