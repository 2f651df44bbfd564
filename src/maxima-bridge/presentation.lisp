;;;; src/maxima-bridge/presentation.lisp -- what the reports ask of Maxima: forms to present, and TeX.
;;;;
;;;; A report writes each quantity as a textbook would; Maxima does the algebra of that. It
;;;; offers candidate forms, each equal to the solved form by Maxima's own algebra (ratsimp,
;;;; factor, grouping sums into factorable parts, trigsimp), and the coefficients of a
;;;; polynomial in a variable (tau). Choosing among the candidates and ordering terms and
;;;; factors is the report's (it knows the scenario's conventions). PRESENTATION-LATEX gives
;;;; Maxima's tex() of a form exactly as the report structured it: no simplification
;;;; reorders it.

(in-package #:ames.maxima)

(defun presentation-candidates (bridge expression)
  "Forms of the arithmetic EXPRESSION to present, each equal to it by Maxima's algebra
under the current assumptions, most direct first: r, factor(r), factor(r) with every
sum grouped into factorable parts, and r's numerator divided term by term, for
r = ratsimp(EXPRESSION) and, when it has
sin, cos or tan, also for r = ratsimp(trigsimp(EXPRESSION)). Candidates Maxima gives
outside the algebra are left out; the list is never empty (EXPRESSION itself comes
last). Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (let* ((form (to-mx bridge expression))
         (answer (maxima-request bridge (mcall "$AMES_PRESENTATION_CANDIDATES" form
                                               (if (trigonometric-form-p form) +true+ +false+))
                                 :datum expression))
         (candidates '()))
    (dolist (candidate (mlist-items answer))
      (let ((translated (handler-case (from-mx bridge candidate)
                          (untranslatable-result () nil))))
        (when translated (pushnew translated candidates :test #'equal))))
    (nreverse (cons expression candidates))))

(defun polynomial-coefficients (bridge expression variable)
  "The list (C0 C1 ... Cd) when EXPRESSION equals C0 + C1 VARIABLE + ... + Cd VARIABLE^d
with every Ci free of VARIABLE (Maxima's ratsimp form of each), else NIL. VARIABLE is a
variable of the algebra (such as TAU). Signals UNTRANSLATABLE-EXPRESSION,
INVALID-BRIDGE-ARGUMENT when VARIABLE is no variable, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (unless (variable-symbol-p variable)
    (error 'invalid-bridge-argument :datum variable :detail "the variable must be a symbol"))
  (if (free-of-p variable expression)
      (list expression)
      (let ((answer (maxima-request bridge (mcall "$AMES_PRESENTATION_COEFFICIENTS"
                                                  (to-mx bridge expression) (to-mx bridge variable))
                                    :datum expression)))
        (and (mform-p answer +mlist+)
             (handler-case (mapcar (lambda (c) (from-mx bridge c)) (mlist-items answer))
               (untranslatable-result () nil))))))

;;; TeX, with the caller's names

(defun tex-with-names (bridge answer name-function)
  "The LaTeX text of Maxima's tex() ANSWER without the surrounding $$, each mangled name
of BRIDGE's table written {(funcall NAME-FUNCTION NAME)} for the variable or quantity
term NAME it stands for."
  (let ((text (string-trim '(#\$ #\Space #\Newline #\Return) (if (stringp answer) answer ""))))
    (cl-ppcre:regex-replace-all
     "(?:\\{\\\\it\\s+)?amesv([a-z]+)(?:\\})?" (substitute #\Space #\Newline text)
     (lambda (match letters)
       (multiple-value-bind (name found)
           (user-name (bridge-names bridge) (wire (concatenate 'string "$AMESV" (string-upcase letters))))
         (if found (format nil "{~A}" (funcall name-function name)) match)))
     :simple-calls t)))

(defun check-name-function (name-function)
  "Signal INVALID-BRIDGE-ARGUMENT unless NAME-FUNCTION is a function designator."
  (unless (or (functionp name-function) (and name-function (symbolp name-function)))
    (error 'invalid-bridge-argument :datum name-function
                                    :detail "the name function must be a function (the caller's LaTeX names)")))

(defun latex (bridge expression &key name-function)
  "The LaTeX of EXPRESSION (arithmetic or a relation), as Maxima's tex() writes it after
its own simplification (without the surrounding $$), each variable or quantity term NAME
written as (funcall NAME-FUNCTION NAME), a LaTeX string (the report's LaTeX names: the
bridge writes none of its own). Signals INVALID-BRIDGE-ARGUMENT without a NAME-FUNCTION,
UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-name-function name-function)
  (tex-with-names bridge
                  (maxima-request bridge (mcall "$TEX" (to-mx bridge expression :any) +false+)
                                  :datum expression)
                  name-function))

(defun presentation-latex (bridge expression &key name-function)
  "The LaTeX of EXPRESSION (arithmetic or a relation) as Maxima's tex() writes it, without
the surrounding $$, and with EXPRESSION's structure kept exactly (nothing is simplified
or reordered: the order of terms and factors is the caller's; see TO-MAXIMA's AS-IS).
Each variable or quantity term NAME is written as (funcall NAME-FUNCTION NAME), a LaTeX
string. Signals INVALID-BRIDGE-ARGUMENT without a NAME-FUNCTION,
UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-name-function name-function)
  (tex-with-names bridge
                  (maxima-request bridge (mcall "$AMES_TEX_AS_IS"
                                                (to-maxima (bridge-names bridge) expression :as-is t))
                                  :datum expression)
                  name-function))
