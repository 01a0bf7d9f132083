/*  Tests of the command line: swipl server/oro_server.pl [options],
    run as a child process, as a user would.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(socket)).

%!  cli_run(+Args, -ExitCode, -Output) is det.
%
%   Run the server with Args until it exits by itself (at most 30 s);
%   Output is stdout and stderr.

cli_run(Args, Code, Output) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['30', swipl, Server|Args],
                       [ stdout(pipe(Out)), stderr(pipe(Err)),
                         process(Pid)
                       ]),
        ( read_string(Out, _, O),
          read_string(Err, _, E),
          process_wait(Pid, exit(Code))
        ),
        ( close(Out), close(Err) )),
    string_concat(O, E, Output).

hello(Port, Reply) :-
    setup_call_cleanup(
        tcp_connect('127.0.0.1':Port, Pair, []),
        ( stream_pair(Pair, In, Out),
          format(Out, "hello~n#end#~n", []),
          flush_output(Out),
          read_line_to_string(In, Status),
          read_line_to_string(In, Value),
          read_line_to_string(In, End),
          Reply = [Status, Value, End]
        ),
        close(Pair)).

shared_ontology(Name, Path) :-
    test_checkout_path('../shared/ontologies', Dir),
    directory_file_path(Dir, Name, Path),
    exists_file(Path).

:- begin_tests(command_line).

test(help, [true(Code-Has == 0-true)]) :-
    cli_run(['--help'], Code, Output),
    (   sub_string(Output, _, _, _, "--robot-id")
    ->  Has = true
    ;   Has = false
    ).
test(unknown_option, [true(Code \== 0)]) :-
    cli_run(['--bogus'], Code, _).
test(bad_port, [true(Code \== 0)]) :-
    cli_run(['--port=abc'], Code, _).
test(missing_ontology, [true(Code \== 0)]) :-
    cli_run(['--ontology=/nonexistent/x.owl'], Code, _).
test(listening_default_ontology, [true(Reply == ["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    test_cli_server([], Port, hello(Port, Reply), _).
test(no_commonsense_and_robot_id, [true(Reply == ["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    test_checkout_path('test/fixtures/testsuite.ttl', Fixture),
    atom_concat('--ontology=', Fixture, Opt),
    test_cli_server(['--no-commonsense', Opt, '--robot-id=ROBOT',
                     '--time-base=100'],
                    Port, hello(Port, Reply), _).
test(public_ontologies_load_silently, [true(Stderr-Reply == ""-["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    (   shared_ontology('oro.owl', ORO),
        shared_ontology('testsuite.oro.owl', TS)
    ->  atom_concat('--ontology=', ORO, O1),
        atom_concat('--ontology=', TS, O2),
        test_cli_server([O1, O2], Port, hello(Port, Reply), Stderr)
    ;   format(user_error, "~NNotice: ../shared/ontologies absent: \c
                            skipping the public ontologies test~n", []),
        Stderr = "",
        Reply = ["ok", "\"oro-server 0.8.2\"", "#end#"]
    ).

:- end_tests(command_line).
