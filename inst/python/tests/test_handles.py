"""A handle's repr is R's print, once: nothing written to the console beside it."""


def test_repr_is_r_print_once(hm, small, capfd):
    models = hm.fit_grasp_models(small, seed=1, mixture_components=1)
    capfd.readouterr()
    text = repr(models)
    out = capfd.readouterr()
    # the R print is in the repr (its first line names the class) ...
    assert text.startswith("<GraspModels>\n<grasp_models>")
    assert text.count("<grasp_models>") == 1
    # ... and was not also written to standard output while the repr was made
    assert "grasp_models" not in out.out and "grasp_models" not in out.err
