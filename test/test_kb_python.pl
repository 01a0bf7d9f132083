:- use_module(library(plunit)).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(oro_test_support).

/*  Runs the Python tests of the pykb-compatible `kb` module
    (clients/python/tests/test_kb.py) with python3, as a child process
    (killed after 300 s at most), from the checkout's root with
    clients/python on PYTHONPATH.  They start their own server.  Skipped
    with a notice when python3 is absent.
*/

python3_found :-
    (   absolute_file_name(path(python3), _,
                           [access(execute), file_errors(fail)])
    ->  true
    ;   print_message(informational,
                      format("test_kb_python: python3 not found: the \c
                              Python tests of the kb module are skipped", [])),
        fail
    ).

:- begin_tests(kb_python, [condition(python3_found)]).

test(unittest, true(Status-Tail == exit(0)-"OK")) :-
    test_checkout_path('.', Root),
    test_checkout_path('clients/python', PythonPath),
    setup_call_cleanup(
        process_create(path(timeout),
                       [ '300', python3, '-m', unittest, discover,
                         '-s', 'clients/python/tests', '-p', 'test_kb.py'
                       ],
                       [ cwd(Root), stdout(null), stderr(pipe(Err)),
                         environment(['PYTHONPATH'=PythonPath]),
                         process(Pid)
                       ]),
        read_string(Err, _, Output),
        close(Err)),
    process_wait(Pid, Status),
    split_string(Output, "\n", " \n", Lines0),
    exclude(==(""), Lines0, Lines),
    last(Lines, Tail0),
    (   Tail0 == "OK"
    ->  Tail = Tail0
    ;   Tail = Output
    ).

:- end_tests(kb_python).
