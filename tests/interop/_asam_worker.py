"""Run ASAM's ``asam-qc-opendrive`` bundle on several files in one process (its start-up costs 2 s per call).

Run by :mod:`tests.interop.asam_harness` with the interpreter of the ASAM virtual environment, never imported by the
test process. Usage: ``python _asam_worker.py CONFIG.xml [CONFIG.xml ...]``: each config file is the one
``qc_opendrive -c CONFIG.xml`` reads, and each is run exactly as that command runs it (a fresh configuration and
result per file, written to the config's ``resultFile``).
"""

import logging
import sys


def main(configs):
    from qc_baselib import Configuration, Result
    from qc_opendrive import constants
    from qc_opendrive.main import run_checks

    logging.disable(logging.INFO)  # the bundle logs every check it starts
    for path in configs:
        config = Configuration()
        config.load_from_file(xml_file_path=path)
        result = Result()
        result.register_checker_bundle(
            name=constants.BUNDLE_NAME,
            description="OpenDrive checker bundle",
            version=constants.BUNDLE_VERSION,
            summary="",
        )
        result.set_result_version(version=constants.BUNDLE_VERSION)
        run_checks(config, result)
        result.copy_param_from_config(config)
        out = config.get_checker_bundle_param(checker_bundle_name=constants.BUNDLE_NAME, param_name="resultFile")
        result.write_to_file(out, generate_summary=True)


if __name__ == "__main__":
    main(sys.argv[1:])
