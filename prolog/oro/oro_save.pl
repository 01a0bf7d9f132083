:- module(oro_save,
          [ oro_save/2,                 % +Model, +File
            oro_save_path/3,            % +File, -Path, -Format
            oro_save_dir/1,             % -Directory
            oro_save_cancel/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(semweb/turtle), [rdf_save_turtle/2]).
:- use_module(library(semweb/rdf_turtle_write), [rdf_save_ntriples/2]).
:- use_module(library(sgml), [xml_quote_attribute/3, xml_quote_cdata/3,
                                xml_name/1]).
:- use_module(library(assoc)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_persist), [oro_persist_directory/1]).

/** <module> Saving a model to a file

oro_save/2 writes what is asserted in a model to a file of the save
directory, in the format its extension names:

  | extension              | format     |
  |------------------------|------------|
  | `.ttl`                 | Turtle     |
  | `.nt`                  | N-Triples  |
  | `.owl`, `.rdf`, other  | RDF/XML    |

RDF/XML writes a predicate as an XML element name: a predicate IRI
whose end is not an XML name (`http://x.org/p<a>`, a trailing `/`...)
cannot be written in it: such a save is refused with
`domain_error(oro_rdf_xml_iri, IRI)`.  Turtle and N-Triples write
every IRI.  RDF/XML is written by write_rdf_xml/2, one
`rdf:Description` per subject, in time proportional to the file's
size (library(rdf_write) takes time in the square of an IRI's length,
and fails on some lists of blank nodes).

## Where a save may write

The file is named relative to the save directory (the setting
`save_dir`), or by an absolute path inside it.  Whatever the name, the
*real* path is decided on (every symbolic link of the directories
resolved), and the save is refused with a permission error when that path is

  - outside the real save directory (a `..` step, an absolute path
    elsewhere, a link to a directory elsewhere);
  - inside the database directory (`--db`), whose journals a save
    would destroy;
  - inside the server's installation (the directory holding
    `prolog/oro.pl`): its sources, README, ontologies.

The file is written to a temporary file next to it, which then
replaces it (rename): a link named like the file is replaced, not
followed, and a save that fails or is cancelled leaves the old file
as it was.  The default save directory is `oro/saves` under the
user's data directory (`$XDG_DATA_HOME`, else `~/.local/share`),
created on the first save.

## Saving blocks no one

The `oro_write` mutex is held only to take an rdf_db snapshot; the
file is written from that snapshot, so writers go on meanwhile.  A
save in progress is stopped by oro_save_cancel/0 (the server calls it
when it shuts down).  The multifile hook oro_save_hook/2 is called
once the snapshot is taken, before writing: tests use it to hold a
save while they show that writes go on.
*/

:- setting(save_dir, atom, '',
           'Directory under which save may write (empty: \c
            $XDG_DATA_HOME/oro/saves or ~/.local/share/oro/saves)').

:- multifile
    oro_save_hook/2.                % +Model, +Path

:- dynamic
    saving/1,                       % Thread
    installation_dir/1.             % Directory

%   installation(-Dir): the directory holding prolog/oro.pl, also the
%   file search path oro_home (its pack.pl, ontologies/).

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.
:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, Prolog),
   file_directory_name(Prolog, Installation),
   assertz(installation_dir(Installation)),
   (   user:file_search_path(oro_home, Installation)
   ->  true
   ;   asserta(user:file_search_path(oro_home, Installation))
   ).

%!  oro_save(+Model, +File) is det.
%
%   Write what is asserted in Model (its ontology layer included, less
%   what it removed) to File of the save directory (see the module
%   doc), in the format its extension names.  The file loads back with
%   oro_init/1's ontologies option.
%
%   @error permission_error(write, oro_file, File) if the file would be
%          outside the save directory (or is a directory),
%          permission_error(write, oro_database_file, File) inside the
%          database directory and
%          permission_error(write, oro_installation_file, File) inside
%          the installation.
%   @error domain_error(oro_rdf_xml_iri, IRI) if RDF/XML cannot write
%          IRI.
%   @error oro_save_cancelled if oro_save_cancel/0 stopped it.

oro_save(Model0, File) :-
    oro_resolve_model(Model0, Model),
    must_be(atom, File),
    oro_save_path(File, Path, Format),
    with_mutex(oro_write, rdf_snapshot(Snapshot)),
    thread_self(Me),
    setup_call_cleanup(
        with_mutex(oro_save, assertz(saving(Me))),
        save_snapshot(Snapshot, Model, Path, Format),
        ( with_mutex(oro_save, retractall(saving(Me))),
          rdf_delete_snapshot(Snapshot)
        )).

save_snapshot(Snapshot, Model, Path, Format) :-
    (   Format == rdf_xml
    ->  in_snapshot(Snapshot,
                    findall(rdf(S, P, O), oro_asserted(Model, S, P, O),
                            Triples)),
        (   member(Triple, Triples),
            xml_unwritable(Triple, IRI)
        ->  domain_error(oro_rdf_xml_iri, IRI)
        ;   true
        )
    ;   true
    ),
    ignore(oro_save_hook(Model, Path)),
    temporary_path(Path, Tmp),
    setup_call_catcher_cleanup(
        true,
        write_file(Format, Snapshot, Model, Triples, Tmp),
        Catcher,
        finished(Catcher, Tmp, Path)),
    debug(oro(save), 'Saved ~w as ~w', [Path, Format]).

in_snapshot(Snapshot, Goal) :-
    rdf_transaction(Goal, oro(save), [snapshot(Snapshot)]).

%   xml_unwritable(+Triple, -IRI): IRI, the predicate of Triple, is
%   one RDF/XML cannot write: it must end in an XML name (the element's
%   local name, after a namespace).

xml_unwritable(rdf(_, P, _), P) :-
    \+ ( iri_xml_namespace(P, _, Local),
         Local \== ''
       ).


temporary_path(Path, Tmp) :-
    thread_self(Me),
    thread_property(Me, id(Id)),
    current_prolog_flag(pid, Pid),
    format(atom(Tmp), '~w.~w-~w.tmp', [Path, Pid, Id]).

finished(exit, Tmp, Path) :-
    !,
    rename_file(Tmp, Path).
finished(_, Tmp, _) :-
    catch(delete_file(Tmp), _, true).

write_file(rdf_xml, _, _, Triples, Tmp) :-
    setup_call_cleanup(open(Tmp, write, Out, [encoding(utf8)]),
                       write_rdf_xml(Out, Triples),
                       close(Out)).
write_file(turtle, Snapshot, Model, _, Tmp) :-
    in_snapshot(Snapshot,
                rdf_save_turtle(Tmp, [ expand(oro_save:saved_triple(Model)),
                                       silent(true)
                                     ])).
write_file(ntriples, Snapshot, Model, _, Tmp) :-
    in_snapshot(Snapshot,
                rdf_save_ntriples(Tmp, [ expand(oro_save:saved_triple(Model)),
                                         silent(true)
                                       ])).

:- public saved_triple/5.

saved_triple(Model, S, P, O, _Graph) :-
    oro_asserted(Model, S, P, O).

%!  oro_save_cancel is det.
%
%   Stop every save in progress: each raises `oro_save_cancelled` and
%   leaves no file behind.

oro_save_cancel :-
    forall(with_mutex(oro_save, saving(Thread)),
           catch(thread_signal(Thread, throw(oro_save_cancelled)), _, true)).

%!  oro_save_dir(-Directory) is det.
%
%   The save directory: the setting `save_dir`, else the default (see
%   the module doc).

oro_save_dir(Dir) :-
    setting(save_dir, Dir0),
    (   Dir0 \== ''
    ->  Dir = Dir0
    ;   getenv('XDG_DATA_HOME', Data),
        Data \== ''
    ->  directory_file_path(Data, 'oro/saves', Dir)
    ;   expand_file_name('~', [Home]),
        Home \== '~'
    ->  directory_file_path(Home, '.local/share/oro/saves', Dir)
    ;   Dir = saves
    ).

%!  oro_save_path(+File, -Path, -Format) is det.
%
%   Path is where oro_save/2 writes File, in Format (`rdf_xml`,
%   `turtle` or `ntriples`), the default save directory being made if
%   needed.
%
%   @error permission_error(write, oro_file, File) as for oro_save/2.

oro_save_path(File, Path, Format) :-
    oro_save_dir(Dir0),
    atomic_list_concat(Parts, /, File),
    (   ( memberchk('..', Parts) ; File == '' )
    ->  permission_error(write, oro_file, File)
    ;   true
    ),
    (   setting(save_dir, '')
    ->  make_directory_path(Dir0)
    ;   true
    ),
    real_path(Dir0, Dir),
    (   is_absolute_file_name(File)
    ->  Named = File
    ;   directory_file_path(Dir0, File, Named)
    ),
    file_directory_name(Named, Parent0),
    file_base_name(Named, Base),
    (   exists_directory(Parent0)
    ->  real_path(Parent0, Parent)
    ;   existence_error(directory, Parent0)
    ),
    directory_file_path(Parent, Base, Path),
    (   \+ within(Dir, Path)
    ->  permission_error(write, oro_file, File)
    ;   exists_directory(Path)
    ->  permission_error(write, oro_file, File)
    ;   oro_persist_directory(Db0),
        real_path(Db0, Db),
        ( within(Db, Path) ; within(Path, Db) )
    ->  permission_error(write, oro_database_file, File)
    ;   installation_dir(Install0),
        real_path(Install0, Install),
        within(Install, Path)
    ->  permission_error(write, oro_installation_file, File)
    ;   true
    ),
    file_name_extension(_, Ext0, Base),
    downcase_atom(Ext0, Ext),
    extension_format(Ext, Format).

extension_format(ttl, turtle) :- !.
extension_format(nt, ntriples) :- !.
extension_format(_, rdf_xml).

%   within(+Dir, +Path): Path is below Dir (both absolute, real).

within(Dir, Path) :-
    (   sub_atom(Dir, _, 1, 0, /)
    ->  Prefix = Dir
    ;   atom_concat(Dir, /, Prefix)
    ),
    atom_concat(Prefix, Rest, Path),
    Rest \== ''.

%   real_path(+Path0, -Path): the absolute path of the existing Path0,
%   every symbolic link in it resolved (as realpath(3) does).

real_path(Path0, Path) :-
    absolute_file_name(Path0, Abs),
    atomic_list_concat([''|Steps], /, Abs),
    foldl(real_step, Steps, '', Path1),
    (   Path1 == ''
    ->  Path = /
    ;   Path = Path1
    ).

real_step('', Path, Path) :-
    !.
real_step(Step, Path0, Path) :-
    atomic_list_concat([Path0, /, Step], Next),
    (   read_link(Next, _, Target)
    ->  absolute_file_name(Target, Path)
    ;   Path = Next
    ).


		 /*******************************
		 *            RDF/XML           *
		 *******************************/

%   write_rdf_xml(+Out, +Triples): Triples (their predicates checked by
%   xml_unwritable/2) as RDF/XML: a namespace declaration per predicate
%   namespace (named by its registered prefix when it has one), then
%   one rdf:Description per subject.  Blank nodes are written as
%   rdf:nodeID b1, b2...

write_rdf_xml(Out, Triples0) :-
    sort(Triples0, Triples),
    findall(NS, ( member(rdf(_, P, _), Triples),
                  iri_xml_namespace(P, NS, _)
                ), NSs0),
    rdf_equal(rdf:'', RDF),
    sort([RDF|NSs0], NSs),
    foldl(namespace_prefix, NSs, Pairs, 1, _),
    list_to_assoc(Pairs, Prefixes),
    bnode_ids(Triples, BNodes),
    format(Out, "<?xml version='1.0' encoding='UTF-8'?>~n<rdf:RDF", []),
    forall(member(NS-Prefix, Pairs),
           ( xml_quote_attribute(NS, Q, utf8),
             format(Out, "~n    xmlns:~w=\"~w\"", [Prefix, Q])
           )),
    format(Out, ">~n", []),
    pairs_by_subject(Triples, Subjects),
    forall(member(S-POs, Subjects),
           write_description(Out, S, POs, Prefixes, BNodes)),
    format(Out, "</rdf:RDF>~n", []).

namespace_prefix(NS, NS-Prefix, N0, N) :-
    (   rdf_current_prefix(Prefix0, NS),
        xml_name(Prefix0),
        \+ sub_atom(Prefix0, _, _, _, ':'),
        \+ sub_atom_icasechk(Prefix0, 0, xml),
        (   Prefix0 == rdf
        ->  rdf_equal(rdf:'', NS)
        ;   true
        )
    ->  Prefix = Prefix0,
        N = N0
    ;   format(atom(Prefix), 'ns~d', [N0]),
        N is N0 + 1
    ).

bnode_ids(Triples, BNodes) :-
    findall(B, ( member(rdf(S, _, O), Triples),
                 member(B, [S, O]),
                 atom(B),
                 rdf_is_bnode(B)
               ), Bs0),
    sort(Bs0, Bs),
    foldl(bnode_id, Bs, Pairs, 1, _),
    list_to_assoc(Pairs, BNodes).

bnode_id(B, B-Id, N0, N) :-
    format(atom(Id), 'b~d', [N0]),
    N is N0 + 1.

pairs_by_subject(Triples, Subjects) :-
    findall(S-(P-O), member(rdf(S, P, O), Triples), Pairs),
    group_pairs_by_key(Pairs, Subjects).

write_description(Out, S, POs, Prefixes, BNodes) :-
    node_attribute(S, about, BNodes, Attribute),
    format(Out, "<rdf:Description ~w>~n", [Attribute]),
    forall(member(P-O, POs),
           write_property(Out, P, O, Prefixes, BNodes)),
    format(Out, "</rdf:Description>~n", []).

node_attribute(Node, _, BNodes, Attribute) :-
    get_assoc(Node, BNodes, Id),
    !,
    format(atom(Attribute), 'rdf:nodeID="~w"', [Id]).
node_attribute(IRI, Name, _, Attribute) :-
    xml_quote_attribute(IRI, Q, utf8),
    format(atom(Attribute), 'rdf:~w="~w"', [Name, Q]).

write_property(Out, P, O, Prefixes, BNodes) :-
    iri_xml_namespace(P, NS, Local),
    get_assoc(NS, Prefixes, Prefix),
    (   O = literal(Literal)
    ->  literal_parts(Literal, Attributes, Lexical),
        text_atom(Lexical, Text),
        xml_quote_cdata(Text, Q, utf8),
        format(Out, "  <~w:~w~w>~w</~w:~w>~n",
               [Prefix, Local, Attributes, Q, Prefix, Local])
    ;   node_attribute(O, resource, BNodes, Attribute),
        format(Out, "  <~w:~w ~w/>~n", [Prefix, Local, Attribute])
    ).

literal_parts(type(Type, Lexical), Attributes, Lexical) :-
    !,
    xml_quote_attribute(Type, Q, utf8),
    format(atom(Attributes), ' rdf:datatype="~w"', [Q]).
literal_parts(lang(Lang, Lexical), Attributes, Lexical) :-
    !,
    xml_quote_attribute(Lang, Q, utf8),
    format(atom(Attributes), ' xml:lang="~w"', [Q]).
literal_parts(Lexical, '', Lexical).

text_atom(Value, Text) :-
    (   atom(Value)
    ->  Text = Value
    ;   format(atom(Text), '~w', [Value])
    ).
