/*  Tests of what an operator uses: the progress and summary of ontology
    loads, the settings file and the settings as options, --debug, the
    request log and its reopening on SIGHUP.  The command-line tests
    run the real server as a child process.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(socket)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(filesex)).
:- use_module(library(settings)).
:- use_module(library(oro)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/server/oro_log)).

:- dynamic
    ops_message/1.                      % oro(Message) printed

ops_tmp_dir(Dir) :-
    tmp_file(oro_ops, Dir),
    make_directory(Dir).

%   ops_hello(+Port, -Reply): the lines of the reply to one hello.

ops_hello(Port, Reply) :-
    ops_request(Port, [hello], Reply).

ops_request(Port, [Method|Params], Reply) :-
    setup_call_cleanup(oro_connect(Port, Conn),
                       oro_call(Conn, Method, Params, Reply),
                       oro_disconnect(Conn)).

ops_file_lines(File, Lines) :-
    (   exists_file(File)
    ->  read_file_to_string(File, Text, []),
        split_string(Text, "\n", "", Lines0),
        exclude(==(""), Lines0, Lines)
    ;   Lines = []
    ).

%   ops_log_has(+File, +N): File has N request lines at least.

ops_log_has(File, N) :-
    ops_file_lines(File, Lines),
    include(ops_request_line, Lines, Requests),
    length(Requests, Len),
    Len >= N.

ops_request_line(Line) :-
    sub_string(Line, _, _, _, " conn=").

                 /*******************************
                 *        ONTOLOGY LOADS        *
                 *******************************/

%   The ontology comes through a named pipe, written in two halves: the
%   test waits (10 s at most) for a progress report of the first half
%   before it writes the second, so that the report is seen whatever
%   the speed of the machine.

:- multifile user:message_hook/3.

user:message_hook(oro(Message), informational, _) :-
    Message =.. [Name|_],
    memberchk(Name, [ontology_loading, ontology_loaded]),
    assertz(ops_message(Message)),
    fail.

ops_half_triples(Out, From, To) :-
    forall(between(From, To, I),
           format(Out, "<http://example.org/ops#i~d> <http://example.org/ops#p> \c
                        <http://example.org/ops#o~d> .~n", [I, I])),
    flush_output(Out).

%   (retractall/1 in a test's body would make a dynamic ops_message/1 of
%   the unit's own.)

ops_forget_messages :-
    retractall(ops_message(_)).

ops_reported_some :-
    ops_message(ontology_loading(_, Triples, _)),
    Triples > 0,
    !.

:- begin_tests(load_reports, [ setup(test_store_testsuite),
                               cleanup(test_store_testsuite)
                             ]).

test(progress_then_summary, true(Summary == 2000)) :-
    ops_forget_messages,
    ops_tmp_dir(Dir),
    directory_file_path(Dir, 'pipe.nt', Pipe),
    process_create(path(mkfifo), [Pipe], [process(Pid)]),
    process_wait(Pid, exit(0)),
    test_with_setting(
        oro_store:load_progress, true,
        test_with_setting(
            oro_store:load_progress_interval, 0.05,
            ( thread_create(oro_load_ontology(Pipe, [silent(false)]),
                            Loader, []),
              setup_call_cleanup(
                  open(Pipe, write, Out),
                  ( ops_half_triples(Out, 1, 1000),
                    test_wait_until(ops_reported_some, 10),
                    ops_half_triples(Out, 1001, 2000)
                  ),
                  close(Out)),
              thread_join(Loader, Status)
            ))),
    delete_directory_and_contents(Dir),
    assertion(Status == true),
    once(ops_message(ontology_loaded(_, Summary, _))).
test(silent_by_default, true(Messages == [])) :-
    ops_forget_messages,
    test_fixture('testsuite.ttl', File),
    test_with_setting(oro_store:load_progress, true,
                      oro_load_ontology(File)),
    findall(M, ops_message(M), Messages).

:- end_tests(load_reports).

                 /*******************************
                 *       SETTINGS, DEBUG        *
                 *******************************/

ops_cli_exit(Args, Code, Stderr) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['30', swipl, Server|Args],
                       [ stdout(null), stderr(pipe(Err)), process(Pid) ]),
        ( read_string(Err, _, Stderr),
          process_wait(Pid, exit(Code))
        ),
        close(Err)).

ops_params(N, Params) :-
    length(Params, N),
    maplist(=("x"), Params).

%   max_params from the config file, then from the option that
%   overrides it: the replies to 3 and 4 parameters tell which applies.

ops_limit_replies(Port, [R3, R4]) :-
    ops_params(3, P3),
    ops_params(4, P4),
    ops_request(Port, [find|P3], R30),
    ops_request(Port, [find|P4], R40),
    ops_reply_kind(R30, R3),
    ops_reply_kind(R40, R4).

ops_reply_kind(Reply, Kind) :-
    (   Reply = error(Name, Message),
        sub_string(Name, _, _, _, "OntologyServerException"),
        sub_string(Message, 0, _, _, "Too many parameters")
    ->  Kind = refused
    ;   Kind = taken
    ).

ops_with_config(Terms, Goal) :-
    ops_tmp_dir(Dir),
    directory_file_path(Dir, 'oro.cfg', File),
    setup_call_cleanup(open(File, write, Out),
                       forall(member(T, Terms), format(Out, "~q.~n", [T])),
                       close(Out)),
    call_cleanup(call(Goal, File),
                 delete_directory_and_contents(Dir)).

ops_config_limit(Extra, Replies, File) :-
    atom_concat('--config=', File, Config),
    test_cli_server([Config|Extra], Port, ops_limit_replies(Port, Replies), _).

:- begin_tests(settings_options).

test(config_file, true(Replies == [refused, refused])) :-
    ops_with_config([setting(max_params, 2)], ops_config_limit([], Replies)).
test(qualified_in_config, true(Replies == [taken, refused])) :-
    ops_with_config([setting(oro_server:max_params, 3)], ops_config_limit([], Replies)).
test(option_overrides_config_wherever_it_is, true(Replies == [taken, taken])) :-
    ops_with_config([setting(max_params, 2)],
                ops_config_limit_first(['--max-params=4'], Replies)).
test(setting_option, true(Replies == [taken, refused])) :-
    test_cli_server(['--max-params=3'], Port, ops_limit_replies(Port, Replies), _).
test(bad_setting_value, true(Code-Said == 1-true)) :-
    ops_cli_exit(['--max-params=many', '--port=0'], Code, Stderr),
    test_bool(sub_string(Stderr, _, _, _, "max_params"), Said).
test(unknown_setting_in_config, true(Code-Said == 1-true)) :-
    ops_with_config([setting(no_such_limit, 3)], ops_config_exit(Code, Stderr)),
    test_bool(sub_string(Stderr, _, _, _, "no_such_limit"), Said).
test(missing_config, true(Code \== 0)) :-
    ops_cli_exit(['--config=/nonexistent/oro.cfg', '--port=0'], Code, _).
test(settings_in_help, true(Listed == true)) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--help'],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_string(Out, _, Help),
          process_wait(Pid, _)
        ),
        close(Out)),
    test_bool(( sub_string(Help, _, _, _, "--max-connections="),
                sub_string(Help, _, _, _, "--time-limit=")
              ), Listed).
test(debug_topic, true(Said == true)) :-
    test_cli_server(['--debug=oro(server)'], Port, ops_hello(Port, _), Stderr),
    test_bool(sub_string(Stderr, _, _, _, "% Listening on"), Said).

:- end_tests(settings_options).

ops_config_limit_first(Extra, Replies, File) :-
    atom_concat('--config=', File, Config),
    append(Extra, [Config], Args),
    test_cli_server(Args, Port, ops_limit_replies(Port, Replies), _).

ops_config_exit(Code, Stderr, File) :-
    atom_concat('--config=', File, Config),
    ops_cli_exit([Config, '--port=0'], Code, Stderr).

                 /*******************************
                 *          REQUEST LOG         *
                 *******************************/

%   ops_log_session(+Extra, -Lines): a server with --log and Extra options
%   answers a hello and a getLabel of an unknown resource; Lines are the
%   request lines of its log.

ops_log_session(Extra, Lines) :-
    ops_tmp_dir(Dir),
    directory_file_path(Dir, 'requests.log', Log),
    atom_concat('--log=', Log, LogOption),
    test_cli_server([LogOption|Extra], Port,
                    ( ops_hello(Port, _),
                      ops_request(Port, [getLabel, "no_such_thing"], _),
                      test_wait_until(ops_log_has(Log, 2), 10)
                    ), _),
    ops_file_lines(Log, All),
    include(ops_request_line, All, Lines),
    delete_directory_and_contents(Dir).

ops_line_fields(Line, Fields) :-
    split_string(Line, " ", "", [Time|Rest]),
    string_length(Time, 24),
    sub_string(Time, 23, 1, 0, "Z"),
    maplist(ops_field, Rest, Fields).

ops_field(Text, Key-Value) :-
    (   sub_string(Text, B, _, A, "=")
    ->  sub_string(Text, 0, B, _, Key),
        sub_string(Text, _, A, 0, Value)
    ;   Key = Text,
        Value = ""
    ).

:- begin_tests(request_log).

test(fields, true(Shapes == [ ["conn", "peer", "method", "ms", "ok"]-"hello",
                              ["conn", "peer", "method", "ms", "error"]-"getLabel"
                            ])) :-
    ops_log_session([], Lines),
    maplist(ops_line_shape, Lines, Shapes).
test(no_payload, true(Leaked == false)) :-
    ops_log_session([], Lines),
    test_bool(( member(Line, Lines),
                sub_string(Line, _, _, _, "no_such_thing")
              ), Leaked).
test(payload_when_asked, true(Params == "[\"no_such_thing\"]")) :-
    ops_log_session(['--log-payload'], Lines),
    member(Line, Lines),
    ops_line_fields(Line, Fields),
    memberchk("method"-"getLabel", Fields),
    !,
    memberchk("params"-Params, Fields).
test(error_names_exception, true(Error == "com.hp.hpl.jena.shared.NotFoundException")) :-
    ops_log_session([], Lines),
    member(Line, Lines),
    ops_line_fields(Line, Fields),
    memberchk("error"-Error, Fields).

%   SIGHUP: the log is renamed (as a rotation does), the server told;
%   the next request goes to a new file of the old name.

test(sighup_reopens, true(Counts == [1, 1])) :-
    ops_tmp_dir(Dir),
    directory_file_path(Dir, 'requests.log', Log),
    directory_file_path(Dir, 'requests.log.1', Old),
    atom_concat('--log=', Log, LogOption),
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(swipl), [Server, LogOption, '--port=0'],
                       [ stdout(pipe(Out)), stderr(null), process(Pid) ]),
        ( read_line_to_string(Out, Line),
          split_string(Line, ":", " ", Parts),
          last(Parts, PortText),
          number_string(Port, PortText),
          ops_hello(Port, _),
          test_wait_until(ops_log_has(Log, 1), 10),
          rename_file(Log, Old),
          process_kill(Pid, hup),
          test_wait_until(exists_file(Log), 10),
          ops_hello(Port, _),
          test_wait_until(ops_log_has(Log, 1), 10)
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          close(Out)
        )),
    maplist(ops_request_count, [Old, Log], Counts),
    delete_directory_and_contents(Dir).

%   In process: a log written, reopened and closed by the library.

test(reopen_in_process, true(Lines == 2)) :-
    ops_tmp_dir(Dir),
    directory_file_path(Dir, 'r.log', Log),
    oro_log_open(Log, []),
    oro_log_request(1, ip(127,0,0,1), request("hello", []), 0.001, ok(x)),
    oro_log_reopen,
    oro_log_request(1, ip(127,0,0,1), request("hello", []), 0.001,
                    error("E", "m")),
    oro_log_close,
    oro_log_request(1, ip(127,0,0,1), request("hello", []), 0.001, ok(x)),
    ops_request_count(Log, Lines),
    delete_directory_and_contents(Dir).

:- end_tests(request_log).

ops_line_shape(Line, Keys-Method) :-
    ops_line_fields(Line, Fields),
    pairs_keys(Fields, Keys),
    memberchk("method"-Method, Fields).

ops_request_count(File, N) :-
    ops_file_lines(File, Lines),
    include(ops_request_line, Lines, Requests),
    length(Requests, N).
