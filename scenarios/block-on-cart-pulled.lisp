;;;; scenarios/block-on-cart-pulled.lisp -- a block rides on a cart pulled along a frictionless floor: it sticks below a threshold force and slides above it.
;;;;
;;;; A fixed floor (y <= 0). A cart, an l by c rectangle of mass mc, on the floor, its
;;;; reference point its bottom-left corner, at (-l/2, 0), pulled by the constant force
;;;; (f, 0). A square block of side b < l and mass m on the middle of the cart's top, its
;;;; reference point the middle of its bottom face, at (0, c). All at rest. Coulomb
;;;; friction between block and cart, MU-K = MU-S = mu; the floor is frictionless.
;;;; Whether f is below or above the threshold mu g (m + mc) is left open (the default
;;;; values, f = 20 and mu g (m + mc) = 3.924, say above).
;;;;
;;;; Expected results (textbook):
;;;;   Threshold force: f* = mu g (m + mc).
;;;;   When f < f*, state 0 lasts forever: the block sticks (static friction); both
;;;;     accelerate at f / (m + mc) along +x; the friction on the block is m f / (m + mc)
;;;;     along +x (within mu m g); N block-cart = m g, N cart-floor = (m + mc) g.
;;;;   When f > f*, state 0: the block slides backward on the cart (kinetic friction
;;;;     mu m g, +x on the block, -x on the cart): block (mu g, 0), cart
;;;;     ((f - mu m g) / mc, 0); relative acceleration (mu g (m + mc) - f) / mc < 0.
;;;;     The block's front bottom corner passes the cart's rear top corner after a
;;;;     relative displacement (l + b)/2, at t1 = sqrt((l + b) mc / (f - mu g (m + mc))):
;;;;     (:leaves block cart :endpoint).
;;;;   With the assumptions alone, which case holds is undecided: the run names the
;;;;   missing fact at the start of state 0.

(scenario block-on-cart-pulled
  "A block rides on a pulled cart: it sticks below the threshold force, slides above."
  (parameters (m :positive (:value 1)) (mc :positive (:value 3))
              (g :positive (:value 981/100)) (mu :positive (:value 1/10))
              (l :positive (:value 2)) (c :positive (:value 1/2))
              (b (> b 0) (< b l) (:value 1/2))
              (f :positive (:value 20)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body cart :mass mc :position ((- (/ l 2)) 0) :velocity (0 0)
             :shape (polygon (0 0) (l 0) (l c) (0 c)))
  (body block :mass m :position (0 c) :velocity (0 0)
              :shape (polygon ((- (/ b 2)) 0) ((/ b 2) 0) ((/ b 2) b) ((- (/ b 2)) b)))
  (force pull :on cart :value (f 0))
  (friction block cart :static mu)
  (simulate :states 2))
