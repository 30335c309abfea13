"""handmotion: natural human hand motion for grasp animation, from Python.

A thin front end over the handmotion R package (through rpy2): the statistics all
run in R; this package converts data and errors. Seeds pass through unchanged, so
results are identical to R's for the same seed.

>>> import handmotion as hm
>>> g = hm.simulate_grasps(subjects=3, seed=1)
>>> m = hm.fit_grasp_models(g, seed=1)
>>> x = hm.generate(m, grasp="Power Sphere", n=10, seed=2)
"""

from .api import (calibrate, calibration_pose_angles, cut_motion, find_motion, glove_profile, read_glove,
                  trim_motion, classify, evaluate_early_recognition, evaluate_generation, evaluate_loso, fit_grasp_classifier,
                  fit_grasp_models, fit_grasp_recognizer, fit_last_frame_pca, fit_weighted_fpca, fit_handover, forward_kinematics, generate,
                  hand_skeleton, joint_names, rank_markers, read_graspdb14, read_hust,
                  read_skeleton, reconstruct, select_markers, simulate_grasps, table_5_1, thesis_table,
                  table_5_2, table_5_3, table_5_6, table_5_7, table_5_8, write_bvh,
                  write_graspdb14, write_hust)
from .errors import (BadFileError, BadInputError, BadRecordingError, BadSkeletonError,
                     DegenerateDataWarning, FitFailedError, HandmotionError, HandmotionWarning, RError,
                     UnknownGraspError)
from .grasps import Grasps
from .view import HandView, hand_3d
from .handles import (GraspClassifier, GraspModels, GraspRecognizer, HandoverModel, RecognitionStream, RHandle,
                      Skeleton)

__version__ = "0.1.0"

__all__ = [
    "Grasps", "GraspModels", "GraspClassifier", "GraspRecognizer", "RecognitionStream", "HandoverModel",
    "RHandle", "Skeleton",
    "HandmotionError", "BadInputError", "BadRecordingError", "UnknownGraspError", "BadFileError",
    "BadSkeletonError", "FitFailedError", "RError", "HandmotionWarning", "DegenerateDataWarning",
    "simulate_grasps", "read_hust", "write_hust", "read_graspdb14", "write_graspdb14",
    "read_skeleton", "hand_skeleton", "forward_kinematics", "joint_names", "write_bvh",
    "fit_grasp_models", "generate", "evaluate_generation", "classify", "evaluate_loso",
    "fit_grasp_classifier", "fit_grasp_recognizer", "evaluate_early_recognition",
    "thesis_table", "table_5_1", "table_5_2", "table_5_3", "table_5_6", "table_5_7", "table_5_8",
    "select_markers", "fit_handover", "reconstruct",
    "hand_3d", "HandView",
    "glove_profile", "read_glove", "calibrate", "calibration_pose_angles", "find_motion", "trim_motion",
    "cut_motion",
]
