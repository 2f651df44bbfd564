;;;; src/scenario/suggestions.lisp -- the hints of the messages about a mistyped word or a shape
;;;; written the wrong way round: "did you mean", and the vertices in the right order.

(in-package #:ames.scenario)

(defun edit-distance (a b)
  "The Levenshtein distance between the strings A and B (case ignored)."
  (let* ((a (string-downcase a)) (b (string-downcase b))
         (previous (make-array (1+ (length b)) :initial-contents (loop for j to (length b) collect j)))
         (current (make-array (1+ (length b)))))
    (loop for i from 1 to (length a)
          do (setf (aref current 0) i)
             (loop for j from 1 to (length b)
                   do (setf (aref current j)
                            (min (1+ (aref previous j)) (1+ (aref current (1- j)))
                                 (+ (aref previous (1- j))
                                    (if (char= (char a (1- i)) (char b (1- j))) 0 1)))))
             (rotatef previous current))
    (aref previous (length b))))

(defun closest-word (word candidates)
  "The string among CANDIDATES (strings or symbols) closest to WORD (a string or symbol)
by edit distance, when it is close enough to be what was meant (at most a third of its
letters differ, or one is the other's prefix); else NIL."
  (let* ((word (string word))
         (best nil) (best-distance nil))
    (dolist (candidate candidates)
      (let* ((text (string-downcase (string candidate)))
             (distance (edit-distance word text)))
        (when (or (null best-distance) (< distance best-distance))
          (setf best text best-distance distance))))
    (and best
         (or (<= (* 3 best-distance) (max (length word) (length best)))
             (and (>= (length word) 3)
                  (eql 0 (search (string-downcase word) best))))
         best)))

(defun did-you-mean (word candidates)
  "\" (did you mean X?)\" for the candidate closest to WORD (CLOSEST-WORD), or \"\"."
  (let ((closest (closest-word word candidates)))
    (if closest (format nil " (did you mean ~A?)" closest) "")))

(defun counter-clockwise-polygon (polygon)
  "The checked POLYGON with its vertices in the opposite order, its first vertex kept
first: the same outline, run the other way round."
  (let ((vertices (rest polygon)))
    (list* (first polygon) (first vertices) (reverse (rest vertices)))))

(defun unclosed-form-position (text start limit)
  "Where, in the form of TEXT from START to LIMIT that lacks a closing parenthesis, the
form that should have been closed most likely begins: the position of the ( that opens
a line, indented as a later line that begins at a deeper depth (two clauses written at
one indentation, the second inside the first). NIL when the indentation shows nothing
(the outermost form lacks its closing parenthesis). Strings and ; comments are skipped;
a guess, for messages only."
  (let ((depth 0) (i start) (line-start t) (column 0)
        (depth-at-column (make-hash-table))
        (n (min limit (length text))))
    (loop while (< i n)
          do (let ((c (char text i)))
               (cond ((char= c #\Newline) (setf line-start t column 0))
                     ((and line-start (member c '(#\Space #\Tab))) (incf column))
                     (t
                      (when (and line-start (char= c #\())
                        (let ((earlier (gethash column depth-at-column)))
                          (when (and earlier (> depth (car earlier)))
                            (return-from unclosed-form-position (cdr earlier)))
                          (setf (gethash column depth-at-column) (cons depth i))))
                      (setf line-start nil)
                      (case c
                        (#\( (incf depth))
                        (#\) (decf depth))
                        (#\; (setf i (1- (or (position #\Newline text :start i :end n) n))))
                        (#\" (incf i)
                         (loop while (and (< i n) (char/= (char text i) #\"))
                               do (when (char= (char text i) #\\) (incf i))
                                  (incf i)))))))
             (incf i))
    nil))
