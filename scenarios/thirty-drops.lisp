;;;; scenarios/thirty-drops.lisp -- thirty particles dropped from symbolically ordered heights.
;;;;
;;;; Particles p1 ... p30 start at rest above a fixed floor (y <= 0), p_i at (2 i, h_i), with
;;;; 0 < h1 < h2 < ... < h30 declared and nothing else known of the heights. They fall
;;;; side by side, each alone.
;;;; (Once, with 26 or more names, the bridge's Maxima names stopped sorting in the order
;;;; they were made, and Maxima's is() could no longer prove the chain of inequalities:
;;;; the run stopped as ambiguous: issue 9.)
;;;;
;;;; Expected results (textbook): every particle falls with A = (0, -g); p_i would land at
;;;; sqrt(2 h_i / g), so the lowest lands first, and the landing order is p1, p2, ..., p30.
;;;;   State 0: duration sqrt(2 h1 / g), (:collision p1 floor), which ends the run; the
;;;;   others are then at heights h_i - h1 > 0.

(scenario thirty-drops
  "Thirty particles dropped from symbolically ordered heights."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h1 :positive (:value 1)) (h2 (> h2 h1) (:value 2)) (h3 (> h3 h2) (:value 3))
              (h4 (> h4 h3) (:value 4)) (h5 (> h5 h4) (:value 5)) (h6 (> h6 h5) (:value 6))
              (h7 (> h7 h6) (:value 7)) (h8 (> h8 h7) (:value 8)) (h9 (> h9 h8) (:value 9))
              (h10 (> h10 h9) (:value 10)) (h11 (> h11 h10) (:value 11))
              (h12 (> h12 h11) (:value 12)) (h13 (> h13 h12) (:value 13))
              (h14 (> h14 h13) (:value 14)) (h15 (> h15 h14) (:value 15))
              (h16 (> h16 h15) (:value 16)) (h17 (> h17 h16) (:value 17))
              (h18 (> h18 h17) (:value 18)) (h19 (> h19 h18) (:value 19))
              (h20 (> h20 h19) (:value 20)) (h21 (> h21 h20) (:value 21))
              (h22 (> h22 h21) (:value 22)) (h23 (> h23 h22) (:value 23))
              (h24 (> h24 h23) (:value 24)) (h25 (> h25 h24) (:value 25))
              (h26 (> h26 h25) (:value 26)) (h27 (> h27 h26) (:value 27))
              (h28 (> h28 h27) (:value 28)) (h29 (> h29 h28) (:value 29))
              (h30 (> h30 h29) (:value 30)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body p1 :mass m :position (2 h1) :velocity (0 0) :shape point)
  (body p2 :mass m :position (4 h2) :velocity (0 0) :shape point)
  (body p3 :mass m :position (6 h3) :velocity (0 0) :shape point)
  (body p4 :mass m :position (8 h4) :velocity (0 0) :shape point)
  (body p5 :mass m :position (10 h5) :velocity (0 0) :shape point)
  (body p6 :mass m :position (12 h6) :velocity (0 0) :shape point)
  (body p7 :mass m :position (14 h7) :velocity (0 0) :shape point)
  (body p8 :mass m :position (16 h8) :velocity (0 0) :shape point)
  (body p9 :mass m :position (18 h9) :velocity (0 0) :shape point)
  (body p10 :mass m :position (20 h10) :velocity (0 0) :shape point)
  (body p11 :mass m :position (22 h11) :velocity (0 0) :shape point)
  (body p12 :mass m :position (24 h12) :velocity (0 0) :shape point)
  (body p13 :mass m :position (26 h13) :velocity (0 0) :shape point)
  (body p14 :mass m :position (28 h14) :velocity (0 0) :shape point)
  (body p15 :mass m :position (30 h15) :velocity (0 0) :shape point)
  (body p16 :mass m :position (32 h16) :velocity (0 0) :shape point)
  (body p17 :mass m :position (34 h17) :velocity (0 0) :shape point)
  (body p18 :mass m :position (36 h18) :velocity (0 0) :shape point)
  (body p19 :mass m :position (38 h19) :velocity (0 0) :shape point)
  (body p20 :mass m :position (40 h20) :velocity (0 0) :shape point)
  (body p21 :mass m :position (42 h21) :velocity (0 0) :shape point)
  (body p22 :mass m :position (44 h22) :velocity (0 0) :shape point)
  (body p23 :mass m :position (46 h23) :velocity (0 0) :shape point)
  (body p24 :mass m :position (48 h24) :velocity (0 0) :shape point)
  (body p25 :mass m :position (50 h25) :velocity (0 0) :shape point)
  (body p26 :mass m :position (52 h26) :velocity (0 0) :shape point)
  (body p27 :mass m :position (54 h27) :velocity (0 0) :shape point)
  (body p28 :mass m :position (56 h28) :velocity (0 0) :shape point)
  (body p29 :mass m :position (58 h29) :velocity (0 0) :shape point)
  (body p30 :mass m :position (60 h30) :velocity (0 0) :shape point)
  (simulate :states 31))
