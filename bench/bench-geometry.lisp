;;;; bench/bench-geometry.lisp -- how long building contacts takes, numeric and symbolic.
;;;; Loaded by bench/run.lisp after the system; prints numbers, asserts nothing.

(in-package #:ames.geometry)

(defun bench-milliseconds (repetitions thunk)
  "Milliseconds per call of THUNK, over REPETITIONS calls."
  (let ((start (get-internal-real-time)))
    (dotimes (i repetitions) (funcall thunk))
    (/ (* 1000.0 (- (get-internal-real-time) start))
       internal-time-units-per-second repetitions)))

(defun bench-pair (form-1 form-2 &optional bridge)
  (make-contact-pair 'one (parse-shape form-1 :bridge bridge)
                     'two (parse-shape form-2 :bridge bridge) :bridge bridge))

(defun bench-regular-polygon (n radius)
  "A convex polygon with N rational vertices near the circle RADIUS."
  (cons 'polygon
        (loop for i below n
              collect (list (rationalize (/ (round (* 100 radius (cos (/ (* 2 pi i) n)))) 100))
                            (rationalize (/ (round (* 100 radius (sin (/ (* 2 pi i) n)))) 100))))))

(let ((l-shape '(polygon (0 0) (2 0) (2 1) (1 1) (1 2) (0 2)))
      (octagon (bench-regular-polygon 8 5))
      (small-octagon (bench-regular-polygon 8 2)))
  (format t "~&Numeric shapes (exact rationals, no Maxima), milliseconds per pair:~%")
  (loop for (label repetitions form-1 form-2)
          in `(("point vs wedge" 200 point (polygon (0 0) (4 0) (0 3)))
               ("block vs block" 200 (polygon (0 0) (2 0) (2 1) (0 1)) (polygon (0 0) (4 0) (4 3) (0 3)))
               ("disc vs wedge (3-4-5)" 100 (circle 1) (polygon (0 0) (4 0) (0 3)))
               ("octagon vs octagon" 50 ,small-octagon ,octagon)
               ("disc vs octagon" 50 (circle 1) ,octagon)
               ("point vs L" 100 point ,l-shape)
               ("block vs L (union of parts)" 20 (polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)) ,l-shape)
               ("disc vs L (union of parts)" 10 (circle 1/4) ,l-shape))
        do (format t "  ~30A ~8,3F~%" label
                   (bench-milliseconds repetitions (lambda () (bench-pair form-1 form-2)))))
  (let ((pair (bench-pair '(polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)) l-shape)))
    (format t "  ~30A ~8,3F~%" "penetrates-p, block vs L"
            (bench-milliseconds 1000 (lambda () (penetrates-p pair '(3/4 3/4)))))
    (format t "  ~30A ~8,3F~%" "contacts-at, block vs L"
            (bench-milliseconds 1000 (lambda () (contacts-at pair '(1 1)))))))

;;; Symbolic shapes: each case with a fresh bridge (its process started first, so that
;;; the time is Maxima's answers, not its start-up), so no answer comes from a warm cache.
(let ((facts '((> h 0) (> a 0) (< a (/ pi 2)) (> rho 0)))
      (wedge '(polygon (0 0) ((/ h (tan a)) 0) (0 h))))
  (format t "~&Symbolic shapes through the bridge (0 < a < pi/2, h > 0), milliseconds:~%")
  (loop for (label form-1 form-2) in `(("point vs wedge" point ,wedge)
                                       ("wedge vs ground" ,wedge (half-plane (1 0) (0 0)))
                                       ("disc vs wedge" (circle rho) ,wedge))
        do (let ((bridge (ames.maxima:make-bridge)))
             (unwind-protect
                  (ames.maxima:with-assumptions (bridge facts)
                    (ames.algebra:decide bridge '(> h 0))
                    (ames.maxima:reset-bridge-statistics bridge)
                    (let* ((pair nil)
                           (time (bench-milliseconds 1 (lambda () (setf pair (bench-pair form-1 form-2 bridge)))))
                           (statistics (ames.maxima:bridge-statistics bridge)))
                      (format t "  ~30A ~8,1F  (~D bridge calls, ~D from its cache)~%"
                              label time (getf statistics :calls) (getf statistics :cache-hits))
                      (when (equal label "point vs wedge")
                        (format t "  ~30A ~8,1F~%" "  then contacts-at the start"
                                (bench-milliseconds
                                 1 (lambda () (contacts-at pair '((/ h (* 2 (tan a))) (/ h 2)))))))))
               (ames.maxima:close-bridge bridge)))))
