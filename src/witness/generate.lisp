(in-package #:ames.witness)
