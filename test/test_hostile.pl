:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).

/*  Tests for hostile clients and heavy operations (issue #36, findings
    1-4): where `save` may write, a save that blocks no writer, the cost
    of nesting and of other parse constructs, and connection slots that
    idle clients cannot hoard.

    Run: swipl test/run_tests.pl test_hostile
*/

:- use_module(library(settings)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(yall)).
:- use_module(library(socket)).
:- use_module(library(readutil)).
:- use_module(library(filesex)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro)).
:- use_module(library(oro/oro_save)).
:- use_module(library(oro/parse/oro_parse)).


                 /*******************************
                 *       WHERE SAVE WRITES      *
                 *******************************/

hostile_tmp_dir(Dir) :-
    tmp_file(oro_hostile, Dir),
    make_directory(Dir).

%   hostile_init_db(-Dir): a save directory Dir holding the database
%   directory Dir/data, with one fact journaled.

hostile_init_db(Dir) :-
    hostile_tmp_dir(Dir),
    directory_file_path(Dir, data, Db),
    oro_init([commonsense(false), db(Db), save_dir(Dir)]),
    oro_add(myself, ["hostile_cup isOn hostile_table"]).

hostile_cleanup(Dir) :-
    oro_close,
    oro_init([commonsense(false)]),
    delete_directory_and_contents(Dir).

hostile_file_text(File, Text) :-
    read_file_to_string(File, Text, [encoding(octet)]).

:- begin_tests(hostile_save_where).

%   The journal is not overwritten: the save is refused, the journal
%   file is what it was, and the fact is restored from it.

test(journal_kept,
     [ setup(hostile_init_db(Dir)),
       cleanup(hostile_cleanup(Dir)),
       true(Got == [refused, same, true])
     ]) :-
    directory_file_path(Dir, 'data/oro.jnl', Journal),
    hostile_file_text(Journal, Before),
    catch(( oro_save(myself, 'data/oro.jnl'), Saved = written ),
          error(permission_error(write, oro_database_file, _), _),
          Saved = refused),
    hostile_file_text(Journal, After),
    (   Before == After
    ->  Same = same
    ;   Same = changed
    ),
    directory_file_path(Dir, data, Db),
    oro_close,
    oro_init([commonsense(false), db(Db)]),
    test_bool(oro_check(myself, ["hostile_cup isOn hostile_table"]), Kept),
    Got = [Saved, Same, Kept].

%   No file of the installation (the checkout) is written, even with the
%   save directory set to it.

test(installation_refused,
     [ setup(( test_checkout_path('.', Checkout),
               oro_init([commonsense(false), save_dir(Checkout)]) )),
       cleanup(( test_checkout_path('hostile_saved.owl', Stray),
                 (   exists_file(Stray)
                 ->  delete_file(Stray)
                 ;   true
                 ),
                 oro_init([commonsense(false)]) )),
       error(permission_error(write, oro_installation_file, _))
     ]) :-
    oro_save(myself, 'hostile_saved.owl').

%   A link inside the save directory to a directory elsewhere is
%   resolved: writing through it is refused, and nothing is written
%   there.

test(symlink_out_refused,
     [ setup(( hostile_tmp_dir(Dir),
               hostile_tmp_dir(Elsewhere),
               directory_file_path(Dir, out, Link),
               link_file(Elsewhere, Link, symbolic),
               oro_init([commonsense(false), save_dir(Dir)]) )),
       cleanup(( delete_directory_and_contents(Dir),
                 delete_directory_and_contents(Elsewhere) )),
       true(Got == refused-[])
     ]) :-
    catch(( oro_save(myself, 'out/x.owl'), Saved = written ),
          error(permission_error(write, oro_file, _), _),
          Saved = refused),
    directory_files(Elsewhere, Entries),
    subtract(Entries, ['.', '..'], Left),
    Got = Saved-Left.

%   Without save_dir the files go to a directory of their own under
%   the user's data directory, made on the first save: not the working
%   directory.

test(default_directory,
     [ setup(( hostile_tmp_dir(Data),
               (   getenv('XDG_DATA_HOME', Old)
               ->  true
               ;   Old = ''
               ),
               setenv('XDG_DATA_HOME', Data),
               oro_init([commonsense(false)]) )),
       cleanup(( (   Old == ''
                 ->  unsetenv('XDG_DATA_HOME')
                 ;   setenv('XDG_DATA_HOME', Old)
                 ),
                 delete_directory_and_contents(Data) )),
       true(Got == [true, false])
     ]) :-
    oro_save(myself, 'hostile_default.owl'),
    directory_file_path(Data, 'oro/saves/hostile_default.owl', Saved),
    test_bool(exists_file(Saved), InData),
    test_bool(exists_file('hostile_default.owl'), InCwd),
    Got = [InData, InCwd].

%   Over the socket: each refusal is an error naming why.

test(socket_refusals,
     [ setup(( hostile_tmp_dir(Dir),
               directory_file_path(Dir, data, Db),
               test_server_start([commonsense(false), db(Db), save_dir(Dir)]) )),
       cleanup(( test_server_stop,
                 hostile_cleanup(Dir) )),
       true(Got == [true, true, ok("")])
     ]) :-
    test_call(save, ["data/oro.jnl"], error(_, Journal)),
    test_call(save, ["../up.owl"], error(_, Up)),
    test_call(save, ["fine.ttl"], Fine),
    test_bool(sub_string(Journal, _, _, _, "database directory"), J),
    test_bool(sub_string(Up, _, _, _, "save directory"), U),
    Got = [J, U, Fine].

:- end_tests(hostile_save_where).


                 /*******************************
                 *         SAVE FORMATS         *
                 *******************************/

hostile_long_predicate(Statement) :-
    length(Codes, 10000),
    maplist(=(0'a), Codes),
    atom_codes(Long, Codes),
    format(string(Statement), "s2 <http://x.org/~w/> o", [Long]).

:- begin_tests(hostile_save_formats,
               [ setup(( hostile_tmp_dir(Dir),
                         oro_init([commonsense(false), save_dir(Dir)]),
                         hostile_long_predicate(Long),
                         oro_add(myself, ["hostile_a isOn hostile_b", Long]) )),
                 cleanup(( oro_init([commonsense(false)]),
                           delete_directory_and_contents(Dir) ))
               ]).

%   RDF/XML cannot write a predicate that does not end in an XML name:
%   refused, with nothing written; Turtle and N-Triples write it and
%   load back.

test(rdf_xml_refused, [error(domain_error(oro_rdf_xml_iri, _))]) :-
    oro_save(myself, 'long.owl').

test(turtle_and_ntriples, [true(Loaded == [true, true])]) :-
    oro_save_dir(Dir),
    maplist(hostile_saved_long(Dir), ['long.ttl', 'long.nt'], Loaded).

hostile_saved_long(Dir, Name, Found) :-
    oro_save(myself, Name),
    directory_file_path(Dir, Name, File),
    setup_call_cleanup(rdf_load(File, [graph(hostile_loaded), silent(true)]),
                       test_bool(( rdf(_, P, _, hostile_loaded),
                                   atom_length(P, Length),
                                   Length > 10000
                                 ), Found),
                       rdf_unload_graph(hostile_loaded)).

:- end_tests(hostile_save_formats).


                 /*******************************
                 *     SAVE BLOCKS NO WRITER    *
                 *******************************/

%   oro_save:oro_save_hook/2 holds a save whose file name has `held`
%   until the test sends `go` on hostile_gate; it says it is held on
%   hostile_held.

:- dynamic hostile_gate/2.              % Gate, Held queues

:- multifile oro_save:oro_save_hook/2.

oro_save:oro_save_hook(_, Path) :-
    sub_atom(Path, _, _, _, held),
    hostile_gate(Gate, Held),
    !,
    thread_send_message(Held, held),
    thread_get_message(Gate, go, [timeout(20)]).

hostile_gates(Gate, Held) :-
    hostile_gates_free,
    message_queue_create(Gate),
    message_queue_create(Held),
    assertz(hostile_gate(Gate, Held)).

hostile_gates_free :-
    forall(retract(hostile_gate(Gate, Held)),
           ( message_queue_destroy(Gate),
             message_queue_destroy(Held)
           )).

:- begin_tests(hostile_save_concurrent,
               [ setup(( hostile_tmp_dir(Dir),
                         test_server_start([commonsense(false), save_dir(Dir)]),
                         assertz(hostile_save_dir(Dir)) )),
                 cleanup(( hostile_gates_free,
                           test_server_stop,
                           forall(retract(hostile_save_dir(Dir)),
                                  delete_directory_and_contents(Dir)),
                           oro_init([commonsense(false)]) ))
               ]).

:- dynamic hostile_save_dir/1.

%   While a save is held (after its snapshot), another client's add is
%   answered, and the file holds what was there before the add.

test(add_during_save, [true(Got == [held, ok(""), ok(""), true, false])]) :-
    hostile_gates(Gate, Held),
    test_ok(add, ["[before_save isOn t1]"]),
    test_server_port(Port),
    oro_connect(Port, Saver),
    call_cleanup(
        ( oro_send(Saver, save, ["held.ttl"]),
          thread_get_message(Held, Signal, [timeout(10)]),
          test_call(add, ["[during_save isOn t1]"], Added),
          thread_send_message(Gate, go),
          oro_receive(Saver, Saved, 10)
        ),
        oro_disconnect(Saver)),
    hostile_save_dir(Dir),
    directory_file_path(Dir, 'held.ttl', File),
    read_file_to_string(File, Text, []),
    test_bool(sub_string(Text, _, _, _, before_save), Before),
    test_bool(sub_string(Text, _, _, _, during_save), During),
    Got = [Signal, Added, Saved, Before, During].

%   oro_save_cancel/0 (run by the shutdown) stops a save in progress:
%   it raises oro_save_cancelled and leaves no file.

test(cancel, [true(Got == [held, exception(oro_save_cancelled), []])]) :-
    hostile_gates(_Gate, Held),
    hostile_save_dir(Dir),
    directory_file_path(Dir, sub, Sub),
    make_directory(Sub),
    thread_create(oro_save(myself, 'sub/held.owl'), Saver, []),
    thread_get_message(Held, Signal, [timeout(10)]),
    oro_save_cancel,
    thread_join(Saver, Status),
    directory_files(Sub, Entries),
    subtract(Entries, ['.', '..'], Left),
    Got = [Signal, Status, Left].

:- end_tests(hostile_save_concurrent).


                 /*******************************
                 *          PARSE COST          *
                 *******************************/

hostile_repeat(N, Text, Repeated) :-
    length(Copies, N),
    maplist(=(Text), Copies),
    atomics_to_string(Copies, Repeated).

:- begin_tests(hostile_parse,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

%   1,000,000 brackets: refused for their nesting (not parsed, not
%   answered false), and the connection goes on.

test(nesting_refused, [true(Got == [true, ok("true")])]) :-
    hostile_repeat(1000000, "[", Open),
    hostile_repeat(1000000, "]", Close),
    atomics_to_string(["[x p ", Open, Close, "]"], Param),
    test_connected(Conn,
                   ( oro_call(Conn, check, [Param], Reply, 60),
                     oro_call(Conn, check, ["[baboon rdf:type Animal]"], Still)
                   )),
    (   Reply = error(_, Message)
    ->  test_bool(sub_string(Message, _, _, _, "nested deeper"), Nested)
    ;   Nested = Reply
    ),
    Got = [Nested, Still].

%   A bracket is not part of a name: nothing is stored.

test(bracket_name, [true(Got == ["laas.openrobots.ontology.exceptions.IllegalStatementException", []])]) :-
    test_call(add, ["[hostile_x hostile_p [[hostile_y]]]"], Reply),
    test_error_name(Reply, Name),
    rdf_global_id(oro:hostile_x, X),
    findall(O, rdf(X, _, O), Stored),
    Got = [Name, Stored].

%   Leading spaces and escaped quotes cost time in proportion to their
%   number (they cost its square: 26 s for 80,000 spaces).

test(leading_spaces, [true(Reply == ok("false"))]) :-
    hostile_repeat(400000, " ", Spaces),
    atomics_to_string(["[\"", Spaces, "hostile_s p \\\"o\\\"\"]"], Param),
    test_connected(Conn, oro_call(Conn, check, [Param], Reply, 20)).

test(escaped_quotes, [true(Reply == ok("false"))]) :-
    hostile_repeat(200000, "a\\\"", Escaped),
    atomics_to_string(["[\"hostile_s p ", Escaped, "\"]"], Param),
    test_connected(Conn, oro_call(Conn, check, [Param], Reply, 20)).

%   8,000,000 empty lines in a request: it is skipped by a search for
%   its #end# (not read line by line, keeping every line: 22 s of CPU
%   and 1 GB), refused, and the connection goes on.

test(many_lines, [true(Got == [true, ok("true")])]) :-
    hostile_repeat(8000000, "\n", Lines),
    atomics_to_string(["add\n", Lines, "[hostile_l p o]\n#end#\n"], Request),
    test_connected(Conn,
                   ( oro_send_raw(Conn, Request),
                     oro_receive(Conn, Reply, 20),
                     oro_call(Conn, check, ["[baboon rdf:type Animal]"], Still)
                   )),
    (   Reply = error(_, Message)
    ->  test_bool(sub_string(Message, _, _, _, "lines"), Refused)
    ;   Refused = Reply
    ),
    Got = [Refused, Still].

%   Parsing has a CPU budget per request: a large request over it
%   gets an error and changes nothing (a budget of 10,000 inferences:
%   parsing 1 MB of statements takes 2,000,000 or more).

test(parse_budget, [true(Got == [true, ok("false")])]) :-
    numlist(1, 50000, Ns),
    maplist([N, S]>>format(string(S), "hostile_s~d p o, ", [N]), Ns, Many),
    atomics_to_string(["["|Many], Start),
    string_concat(Start, "hostile_s p o]", Param),
    test_with_setting(oro_parse:inference_limit, 10000,
                      test_call(add, [Param], Reply)),
    (   Reply = error(_, Message)
    ->  test_bool(sub_string(Message, _, _, _, "Parse budget"), Limited)
    ;   Limited = Reply
    ),
    test_call(check, ["[hostile_s p o]"], Added),
    Got = [Limited, Added].

:- end_tests(hostile_parse).


                 /*******************************
                 *      CONNECTION HOARDING     *
                 *******************************/

%   hostile_connect_from(+Address, -Conn): a connection to the unit's
%   server from the loopback Address (127.0.0.2...).

hostile_connect_from(Address, oro_conn(In, Out, Events, Replies)) :-
    test_server_port(Port),
    tcp_socket(Socket),
    catch(( tcp_bind(Socket, Address:_),
            tcp_connect(Socket, '127.0.0.1':Port)
          ), E,
          ( tcp_close_socket(Socket),
            throw(E)
          )),
    tcp_open_socket(Socket, Pair),
    stream_pair(Pair, In, Out),
    maplist([S]>>set_stream(S, encoding(utf8)), [In, Out]),
    message_queue_create(Events),
    message_queue_create(Replies).

hostile_served(Address, Reply) :-
    hostile_connect_from(Address, Conn),
    call_cleanup(oro_call(Conn, check, ["[baboon rdf:type Animal]"], Reply, 10),
                 oro_disconnect(Conn)).

hostile_served_now(Address) :-
    catch(hostile_served(Address, ok("true")), _, fail).

hostile_start_limited :-
    set_setting(oro_server:max_connections, 8),
    test_server_start_testsuite.

hostile_stop_limited :-
    test_server_stop,
    restore_setting(oro_server:max_connections).

:- begin_tests(hostile_connections,
               [ setup(hostile_start_limited),
                 cleanup(hostile_stop_limited)
               ]).

%   By default an idle connection is closed within a minute, and one
%   address cannot take every connection.

test(defaults, [true(Got == [true, true])]) :-
    setting_property(oro_server:idle_timeout, default(Idle)),
    setting_property(oro_server:max_per_address, default(PerAddress)),
    setting_property(oro_server:max_connections, default(Max)),
    test_bool(( Idle > 0, Idle =< 60 ), IdleBounded),
    test_bool(( PerAddress > 0, PerAddress < Max ), Capped),
    Got = [IdleBounded, Capped].

%   The server full of silent clients from 127.0.0.1: a newcomer from
%   127.0.0.2 and one from 127.0.0.1 are served once the silent ones
%   are closed for idleness.

test(hoarded_slots_freed, [true(Got == [true, true])]) :-
    test_wait_until(test_server_connections(0), 10),
    test_with_setting(oro_server:idle_timeout, 0.5,
        ( length(Silent, 8),
          maplist(hostile_connect_from('127.0.0.1'), Silent),
          call_cleanup(
              ( test_bool(test_wait_until(hostile_served_now('127.0.0.2'), 15), Other),
                test_bool(test_wait_until(hostile_served_now('127.0.0.1'), 15), Same)
              ),
              maplist(oro_disconnect, Silent))
        )),
    Got = [Other, Same].

%   At most max_per_address connections from one address: the next is
%   refused, one from another address is served at once.

test(per_address_cap, [true(Got == [refused, ok("true")])]) :-
    test_wait_until(test_server_connections(0), 10),  % earlier tests' gone
    test_with_setting(oro_server:max_per_address, 3,
        ( length(Held, 3),
          maplist(hostile_connect_from('127.0.0.1'), Held),
          call_cleanup(
              ( maplist([C]>>oro_call(C, check, ["[baboon rdf:type Animal]"], ok(_), 10), Held),
                hostile_connect_from('127.0.0.1', Extra),
                call_cleanup(oro_receive(Extra, Message, 10), oro_disconnect(Extra)),
                (   Message = error(_, Text),
                    sub_string(Text, _, _, _, "Too many connections")
                ->  Fourth = refused
                ;   Fourth = Message
                ),
                hostile_served('127.0.0.2', Other)
              ),
              maplist(oro_disconnect, Held))
        )),
    Got = [Fourth, Other].

%   A client subscribed to events and silent is never closed for
%   idleness: it gets its event long after the idle timeout.

test(subscriber_kept, [true(Got == [ok, timeout, event])]) :-
    test_with_setting(oro_server:idle_timeout, 0.3,
        ( test_server_port(Port),
          oro_connect(Port, Waiter),
          call_cleanup(
              ( oro_call(Waiter, registerEvent,
                         ["FACT_CHECKING", "ON_TRUE", "[hostile_kong rdf:type Monkey]"],
                         Registered),
                oro_receive(Waiter, Quiet, 1.5),
                test_call(add, ["[hostile_kong rdf:type Monkey]"], ok(_)),
                oro_next_event(Waiter, Event, 10)
              ),
              oro_disconnect(Waiter))
        )),
    functor(Registered, R, _),
    functor(Event, E, _),
    Got = [R, Quiet, E].

%   The command line sets the policies.

test(options, [true(Got == [5, 4, 2])]) :-
    test_server_stop,
    setup_call_cleanup(
        test_server_start([ commonsense(false), idle_timeout(5),
                            max_connections(4), max_per_address(2)
                          ]),
        maplist([S, V]>>setting(oro_server:S, V),
                [idle_timeout, max_connections, max_per_address], Got),
        ( test_server_stop,
          maplist(restore_setting,
                  [ oro_server:idle_timeout, oro_server:max_per_address ]),
          set_setting(oro_server:max_connections, 8),
          test_server_start_testsuite
        )).

:- end_tests(hostile_connections).
