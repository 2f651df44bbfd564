;;;; src/kb/event-kinds.lisp -- the kinds of event the knowledge base declares, for the
;;;; validation of a query's (:KIND NAME ...) pattern.
;;;;
;;;; A query may name the moment of an event as the event is printed, (:collision a b). The
;;;; scenario layer, below this one, cannot know the kinds; it asks the function in
;;;; AMES.SCENARIO:*EVENT-KINDS*, which this file sets: the kinds of the phenomena's
;;;; :EVENT descriptions and those the components' :EVENT and :IMPACT specifications name.

(in-package #:ames.kb)

(defun specification-event-kinds (form)
  "The keywords KIND of the (KIND ...) that follow :EVENT or :IMPACT anywhere in FORM."
  (let ((found '()))
    (labels ((walk (x)
               (when (consp x)
                 (loop for (key value) on x
                       while (consp value)
                       when (and (member key '(:event :impact)) (keywordp (car value)))
                         do (pushnew (car value) found))
                 (loop for rest on x while (consp rest) do (walk (car rest))))))
      (walk form))
    found))

(defun declared-event-kinds ()
  "Every kind of event the knowledge base declares (keywords, each once)."
  (remove-duplicates
   (append (loop for phenomenon in *phenomena*
                 append (mapcar #'first (phenomenon-events phenomenon)))
           (loop for component in (ames.engine:knowledge-base-components *mechanics*)
                 append (specification-event-kinds (ames.engine:component-definition component))))))

(setf ames.scenario:*event-kinds* #'declared-event-kinds)
